#pragma once
// The study programs' options: pairs "--name value". --help, an unknown
// name or a name without its value prints the usage and exits (0, or 2 on a
// mistake), so a typo never starts a long run with the defaults.

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace fixel::bench {

inline void check_study_args(int argc, char** argv, const std::string& usage, const std::vector<std::string>& names) {
  for (int i = 1; i < argc; i += 2) {
    const std::string a = argv[i];
    const bool help = a == "--help" || a == "-h";
    bool known = false;
    for (const auto& n : names) known = known || a == n;
    if (help) {
      std::cout << usage << "\n";
      std::exit(0);
    }
    if (!known || i + 1 >= argc) {
      std::cerr << (known ? "missing value for " : "unknown option ") << a << "\n" << usage << "\n";
      std::exit(2);
    }
  }
}

}  // namespace fixel::bench
