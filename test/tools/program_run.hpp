#pragma once

// Runs a built program as a user would, through the shell, for the tests of src/tools/.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace ari_social_sim::tools::test {

struct ProgramRun {
  int status{-1};  // exit code; -1 when killed by a signal
  std::string out;
  std::string err;
};

inline std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs `program` with `arguments` (shell syntax), capturing its output and exit status; the
/// captures go to files named after `program` in the test's temporary folder, standard output to
/// `stdout_path` instead when given (then `out` is empty).
inline ProgramRun run_program(const std::string& program, const std::string& arguments,
                              const std::string& stdout_path = "") {
  const std::string stem = ::testing::TempDir() + program.substr(program.rfind('/') + 1);
  const std::string command = program + " " + arguments + " >" +
                              (stdout_path.empty() ? stem + "_stdout.txt" : stdout_path) + " 2>" +
                              stem + "_stderr.txt";
  const int raw = std::system(command.c_str());
  ProgramRun result;
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  result.out = stdout_path.empty() ? read_all(stem + "_stdout.txt") : "";
  result.err = read_all(stem + "_stderr.txt");
  return result;
}

/// Expects exit code 2 (bad input) and a message on standard error holding `fragment`.
inline void expect_refused(const ProgramRun& result, const std::string& fragment) {
  EXPECT_EQ(result.status, 2) << result.err;
  EXPECT_NE(result.err.find(fragment), std::string::npos)
      << "'" << fragment << "' not in: " << result.err;
}

}  // namespace ari_social_sim::tools::test
