// parameter_docs: prints docs/parameters.md, generated from the config structs' definitions.
//   rosrun ari_social_sim parameter_docs > docs/parameters.md

#include <iostream>

#include "parameters_page.hpp"

int main(int argc, char** argv) {
  if (argc > 1) {
    std::cerr << "usage: parameter_docs > docs/parameters.md\n";
    return 2;
  }
  std::cout << ari_social_sim::tools::parameters_page();
  return 0;
}
