#pragma once

// Runs a built program as a user would, through the shell, for the tests of src/tools/.

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>

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

/// Starts `program` with `arguments` (shell syntax) in the background as a script would: with
/// SIGINT ignored (a non-interactive shell starts background jobs so), through `exec` so that the
/// signals a test sends reach the program, not the shell. Output and error go to the files given.
/// Returns the program's process id, or -1 when it cannot be started.
inline pid_t start_in_background(const std::string& program, const std::string& arguments,
                                 const std::string& stdout_path, const std::string& stderr_path) {
  const std::string command =
      "trap '' INT; exec " + program + " " + arguments + " >" + stdout_path + " 2>" + stderr_path;
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  pid_t pid = -1;
  return posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ) == 0
             ? pid
             : -1;
}

/// Polls `ready` every 5 ms until it holds (true) or `limit` passes (false): a test waits for a
/// file to appear, never for a fixed time that a busy machine would break.
inline bool wait_until(const std::function<bool()>& ready,
                       std::chrono::seconds limit = std::chrono::seconds(120)) {
  const auto give_up = std::chrono::steady_clock::now() + limit;
  while (!ready()) {
    if (std::chrono::steady_clock::now() > give_up) {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

/// Sends `signal` to `pid` and waits for it to end: its exit code, or 128 + the signal's number
/// when the signal killed it (as a shell reports both).
inline int signal_and_wait(pid_t pid, int signal) {
  kill(pid, signal);
  int raw = 0;
  if (waitpid(pid, &raw, 0) != pid) {
    return -1;
  }
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

}  // namespace ari_social_sim::tools::test
