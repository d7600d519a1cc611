// parameter_docs: prints docs/parameters.md, generated from the config structs' definitions.
//   rosrun ari_social_sim parameter_docs > docs/parameters.md
//
// Unlike the batch tools it installs no stop handler (core/stop_signal.hpp): it has no units of
// work to stop between (the page is made in milliseconds and printed at its end) and no output
// file of its own to keep whole (standard output is the caller's); SIGINT or SIGTERM ends it at
// once, with the exit status a shell reports for that signal.

#include <iostream>

#include "parameters_page/parameters_page.hpp"

int main(int argc, char** argv) {
  if (argc > 1) {
    std::cerr << "usage: parameter_docs > docs/parameters.md\n";
    return 2;
  }
  std::cout << ari_social_sim::tools::parameters_page();
  return 0;
}
