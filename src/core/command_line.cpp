#include "ari_social_sim/core/command_line.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::core {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const char* option, const std::string& message) {
  throw ConfigError(std::string(option) + ": " + message);
}

// Whether a new file can be made in `dir`: creating one is the only test that holds for root
// (who passes every permission check) and for read-only mounts.
bool accepts_new_files(const fs::path& dir, std::string& reason) {
  const fs::path probe = dir / (".ari_write_probe_" + std::to_string(::getpid()));
  std::ofstream out(probe);
  if (!out) {
    reason = std::strerror(errno);
    return false;
  }
  out.close();
  std::error_code ignored;
  fs::remove(probe, ignored);
  return true;
}

}  // namespace

std::string IntegerOption::range() const {
  return "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
}

int64_t IntegerOption::parse(const std::string& text) const {
  // strtoll alone would accept leading spaces and a `+`, and stop silently at the first
  // character that is not a digit.
  const size_t first_digit = !text.empty() && text[0] == '-' ? 1 : 0;
  const bool digits_only = text.size() > first_digit &&
                           text.find_first_not_of("0123456789", first_digit) == std::string::npos;
  if (digits_only) {
    errno = 0;
    const long long value = std::strtoll(text.c_str(), nullptr, 10);
    if (errno != ERANGE && value >= min && value <= max) {
      return value;
    }
  }
  fail(name, "expected an integer in " + range() + ", got '" + text + "'");
}

double NumberOption::parse(const std::string& text) const {
  char* end = nullptr;
  const double value = text.empty() || std::isspace(static_cast<unsigned char>(text[0]))
                           ? NAN
                           : std::strtod(text.c_str(), &end);
  if (std::isfinite(value) && *end == '\0' && bounds.contains(value)) {
    return value;
  }
  std::string expectation = "expected a finite number";
  const std::string range = bounds.describe();  // `[0, 1]` or `> 0`
  if (!range.empty()) {
    expectation += (range[0] == '[' || range[0] == '(' ? " in " : " ") + range;
  }
  fail(name, expectation + ", got '" + text + "'");
}

std::string option_value(int argc, char** argv, int& i) {
  const std::string option = argv[i];
  if (i + 1 >= argc) {
    fail(option.c_str(), "expected a value after it");
  }
  std::string value = argv[++i];
  if (value.empty()) {
    fail(option.c_str(), "expected a value, got ''");
  }
  return value;
}

void check_known_option(const std::string& option, const std::vector<std::string>& known) {
  if (std::find(known.begin(), known.end(), option) != known.end()) {
    return;
  }
  std::string list;
  for (const std::string& name : known) {
    list += (list.empty() ? "" : ", ") + name;
  }
  fail(option.c_str(), "unknown option, expected one of " + list);
}

void check_input_file(const char* option, const std::string& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) {
    fail(option, path + ": expected a readable file, got a directory");
  }
  std::ifstream in(path);
  if (!in) {
    fail(option, path + ": cannot open the file (" +
                     (errno == ELOOP ? "a symbolic link loop" : std::strerror(errno)) + ")");
  }
}

void check_input_directory(const char* option, const std::string& path) {
  std::error_code error;
  if (!fs::is_directory(path, error)) {
    fail(option, path + ": expected a directory, got " +
                     (fs::exists(path, error) ? "a file" : "nothing (no such path)"));
  }
}

void check_output_file(const char* option, const std::string& path, bool replace) {
  if (path.empty()) {
    fail(option, "expected a file name, got ''");
  }
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error == std::errc::too_many_symbolic_link_levels) {
    fail(option, path + ": expected a file name, got a symbolic link loop");
  }
  if (fs::is_directory(status)) {
    fail(option, path + ": expected a file name, got a directory");
  }
  if (fs::exists(status) && !replace) {
    fail(option, path + ": exists (pass --overwrite to replace it)");
  }
  const fs::path parent = fs::path(path).parent_path();
  const fs::path dir = parent.empty() ? fs::path(".") : parent;
  if (!fs::is_directory(dir, error)) {
    fail(option, path + ": its folder " + dir.string() + " does not exist");
  }
  std::string reason;
  if (!accepts_new_files(dir, reason)) {
    fail(option, path + ": cannot write in " + dir.string() + " (" + reason + ")");
  }
}

void prepare_output_directory(const char* option, const std::string& path) {
  if (path.empty()) {
    fail(option, "expected a directory, got ''");
  }
  std::error_code error;
  if (fs::exists(path, error) && !fs::is_directory(path, error)) {
    fail(option, path + ": expected a directory, got a file");
  }
  fs::create_directories(path, error);
  if (error) {
    fail(option, path + ": cannot create the directory (" + error.message() + ")");
  }
  std::string reason;
  if (!accepts_new_files(path, reason)) {
    fail(option, path + ": cannot write in the directory (" + reason + ")");
  }
}

}  // namespace ari_social_sim::core
