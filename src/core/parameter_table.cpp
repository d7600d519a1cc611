#include "ari_social_sim/core/parameter_table.hpp"

namespace ari_social_sim::core {
namespace {

// A table cell: a '|' would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    out += c == '|' ? std::string("\\|") : std::string(1, c);
  }
  return out;
}

std::string joined(const std::vector<std::string>& path, const std::string& prefix,
                   const std::string& separator) {
  std::string text = prefix;
  for (size_t i = 0; i < path.size(); ++i) {
    text += (i == 0 ? "" : separator) + path[i];
  }
  return "`" + text + "`";
}

}  // namespace

void ParameterTable::add(const Key& key, std::string type, std::string default_value,
                         std::string range, const char* meaning) {
  rows_.push_back(
      {path_of(key.name), std::move(type), std::move(default_value), std::move(range), meaning});
}

std::vector<std::string> ParameterTable::path_of(const std::string& name) const {
  std::vector<std::string> path = prefix_;
  path.push_back(name);
  return path;
}

std::string ParameterTable::markdown(const std::string& prefix,
                                     const std::string& separator) const {
  std::string text = "| parameter | type | default | range | meaning |\n|---|---|---|---|---|\n";
  for (const ParameterRow& row : rows_) {
    text += "| " + joined(row.path, prefix, separator) + " | " + row.type + " | " +
            cell(row.default_value) + " | " + cell(row.range) + " | " + cell(row.meaning) + " |\n";
  }
  if (!rules_.empty()) {
    text += "\nChecked together:\n\n";
    for (const ParameterRule& rule : rules_) {
      text += "- " + joined(rule.path, prefix, separator) + ": " + rule.expectation + "\n";
    }
  }
  return text;
}

}  // namespace ari_social_sim::core
