#include "ari_social_sim/core/yaml_map.hpp"

#include <cmath>
#include <sstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/text_file.hpp"

namespace ari_social_sim::core {
namespace {

bool is_scalar(const YAML::Node& node) {
  return node.IsScalar();
}

}  // namespace

YamlMap::YamlMap(const YAML::Node& node, std::string source, std::string path)
    : node_(node), source_(std::move(source)), path_(std::move(path)) {
  if (!node_.IsMap()) {
    throw ConfigError(source_ + ": " + (path_.empty() ? std::string("top level") : path_) +
                      ": expected a mapping of key: value, got " + render(node_));
  }
}

YamlMap YamlMap::load_file(const std::string& file_path) {
  return parse(read_text_file(file_path, "a YAML file", kMaxYamlFileBytes), file_path);
}

YamlMap YamlMap::parse(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source + ": not valid YAML: " + e.what());
  }
  return YamlMap(root, source);
}

bool YamlMap::has(const std::string& key) const {
  return static_cast<bool>(node_[key]);
}

std::string YamlMap::where() const {
  return path_.empty() ? source_ : source_ + ": " + path_;
}

std::string YamlMap::field_name(const std::string& key) const {
  return source_ + ": " + (path_.empty() ? key : path_ + "." + key);
}

void YamlMap::fail(const std::string& key, const std::string& expectation,
                   const std::string& got) const {
  throw ConfigError(field_name(key) + ": expected " + expectation + ", got " + got);
}

std::string YamlMap::render(const YAML::Node& node) {
  if (!node) {
    return "nothing";
  }
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

YAML::Node YamlMap::value_node(const std::string& key) const {
  read_keys_.insert(key);
  return node_[key];
}

namespace {

// Conversions from one YAML node to a value, each with the words used in error messages.
template <class T>
struct Reader;

template <>
struct Reader<double> {
  static constexpr const char* kWhat = "a number";
  static constexpr const char* kWhatMany = "numbers";  // in "a list of ..."
  static bool read(const YAML::Node& n, double& out) {
    if (!is_scalar(n)) {
      return false;
    }
    try {
      out = n.as<double>();
    } catch (const YAML::Exception&) {
      return false;
    }
    return std::isfinite(out);
  }
  static double as_number(double v) { return v; }
};

template <>
struct Reader<int> {
  static constexpr const char* kWhat = "an integer";
  static bool read(const YAML::Node& n, int& out) {
    if (!is_scalar(n)) {
      return false;
    }
    try {
      out = n.as<int>();
    } catch (const YAML::Exception&) {
      return false;
    }
    return true;
  }
  static double as_number(int v) { return v; }
};

template <>
struct Reader<unsigned> {
  static constexpr const char* kWhat = "a non-negative integer";
  static constexpr const char* kWhatMany = "non-negative integers";  // in "a list of ..."
  static bool read(const YAML::Node& n, unsigned& out) {
    int value = 0;
    if (!Reader<int>::read(n, value) || value < 0) {
      return false;
    }
    out = static_cast<unsigned>(value);
    return true;
  }
  static double as_number(unsigned v) { return v; }
};

template <>
struct Reader<bool> {
  static constexpr const char* kWhat = "true or false";
  static bool read(const YAML::Node& n, bool& out) {
    if (!is_scalar(n)) {
      return false;
    }
    try {
      out = n.as<bool>();
    } catch (const YAML::Exception&) {
      return false;
    }
    return true;
  }
};

template <>
struct Reader<std::string> {
  static constexpr const char* kWhat = "a string";
  static constexpr const char* kWhatMany = "strings";  // in "a list of ..."
  static bool read(const YAML::Node& n, std::string& out) {
    if (!is_scalar(n)) {
      return false;
    }
    out = n.as<std::string>();
    return true;
  }
};

template <class T>
constexpr bool kIsNumber = std::is_arithmetic_v<T> && !std::is_same_v<T, bool>;

template <class T>
bool read_list(const YAML::Node& n, std::vector<T>& out) {
  if (!n.IsSequence()) {
    return false;
  }
  out.clear();
  for (const YAML::Node& item : n) {
    T value{};
    if (!Reader<T>::read(item, value)) {
      return false;
    }
    out.push_back(value);
  }
  return true;
}

}  // namespace

template <class T>
T YamlMap::required(const std::string& key, const Bounds& bounds) const {
  const YAML::Node n = value_node(key);
  if (!n) {
    fail(key, "a value (the field is required)", "nothing");
  }
  const std::string range = bounds.describe();
  if constexpr (std::is_same_v<T, std::vector<Eigen::Vector2d>>) {
    T points;
    bool ok = n.IsSequence();
    for (size_t i = 0; ok && i < n.size(); ++i) {
      std::vector<double> xy;
      ok =
          read_list(n[i], xy) && xy.size() == 2 && bounds.contains(xy[0]) && bounds.contains(xy[1]);
      if (ok) {
        points.emplace_back(xy[0], xy[1]);
      }
    }
    if (!ok) {
      fail(key, "a list of points [[x, y], ...]" + (range.empty() ? "" : ", each " + range),
           render(n));
    }
    return points;
  } else if constexpr (std::is_same_v<T, Eigen::Vector2d>) {
    std::vector<double> values;
    if (!read_list(n, values) || values.size() != 2 || !bounds.contains(values[0]) ||
        !bounds.contains(values[1])) {
      fail(key, "2 numbers [x, y]" + (range.empty() ? "" : ", each " + range), render(n));
    }
    return Eigen::Vector2d(values[0], values[1]);
  } else if constexpr (std::is_same_v<T, std::vector<double>> ||
                       std::is_same_v<T, std::vector<unsigned>> ||
                       std::is_same_v<T, std::vector<std::string>>) {
    using Item = typename T::value_type;
    T values;
    bool in_bounds = true;
    const bool ok = read_list(n, values);
    if constexpr (kIsNumber<Item>) {
      for (Item v : values) {
        in_bounds = in_bounds && bounds.contains(static_cast<double>(v));
      }
    }
    if (!ok || !in_bounds) {
      fail(key,
           std::string("a list of ") + Reader<Item>::kWhatMany +
               (range.empty() ? "" : ", each " + range),
           render(n));
    }
    return values;
  } else {
    T value{};
    if (!Reader<T>::read(n, value)) {
      fail(key, std::string(Reader<T>::kWhat) + (range.empty() ? "" : " " + range), render(n));
    }
    if constexpr (kIsNumber<T>) {
      if (!bounds.contains(static_cast<double>(value))) {
        fail(key, std::string(Reader<T>::kWhat) + " " + range, render(n));
      }
    }
    return value;
  }
}

template <class T>
T YamlMap::optional(const std::string& key, const T& fallback, const Bounds& bounds) const {
  if (!has(key)) {
    read_keys_.insert(key);
    return fallback;
  }
  return required<T>(key, bounds);
}

YamlMap YamlMap::map(const std::string& key) const {
  const YAML::Node n = value_node(key);
  if (!n) {
    fail(key, "a mapping (the field is required)", "nothing");
  }
  if (!n.IsMap()) {
    fail(key, "a mapping of key: value", render(n));
  }
  return YamlMap(n, source_, path_.empty() ? key : path_ + "." + key);
}

std::vector<YamlMap> YamlMap::list(const std::string& key, bool allow_missing) const {
  const YAML::Node n = value_node(key);
  std::vector<YamlMap> items;
  if (!n) {
    if (!allow_missing) {
      fail(key, "a list (the field is required)", "nothing");
    }
    return items;
  }
  if (!n.IsSequence()) {
    fail(key, "a list", render(n));
  }
  const std::string base = path_.empty() ? key : path_ + "." + key;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string item_path = base + "[" + std::to_string(i) + "]";
    if (!n[i].IsMap()) {
      throw ConfigError(source_ + ": " + item_path + ": expected a mapping of key: value, got " +
                        render(n[i]));
    }
    items.emplace_back(n[i], source_, item_path);
  }
  return items;
}

void YamlMap::finish() const {
  std::string unknown;
  for (const auto& entry : node_) {
    const std::string key = entry.first.as<std::string>();
    if (read_keys_.count(key) == 0) {
      unknown += (unknown.empty() ? "" : ", ") + key;
    }
  }
  if (!unknown.empty()) {
    throw ConfigError(source_ + ": " + (path_.empty() ? std::string("top level") : path_) +
                      ": unknown field(s) " + unknown + " (check the spelling)");
  }
}

#define ARI_INSTANTIATE(T)                                                  \
  template T YamlMap::required<T>(const std::string&, const Bounds&) const; \
  template T YamlMap::optional<T>(const std::string&, const T&, const Bounds&) const;
ARI_INSTANTIATE(double)
ARI_INSTANTIATE(int)
ARI_INSTANTIATE(unsigned)
ARI_INSTANTIATE(bool)
ARI_INSTANTIATE(std::string)
ARI_INSTANTIATE(Eigen::Vector2d)
ARI_INSTANTIATE(std::vector<double>)
ARI_INSTANTIATE(std::vector<unsigned>)
ARI_INSTANTIATE(std::vector<std::string>)
ARI_INSTANTIATE(std::vector<Eigen::Vector2d>)
#undef ARI_INSTANTIATE

}  // namespace ari_social_sim::core
