// specular_constants: the minimax search for the constants on pins 19 and 20, in one
// command (issue 14). Prints the trade-off table (pin 19's fraction bits F, the extra
// bits multiplier 6 takes, the largest error) and writes it as CSV; the constants
// frozen in modules/src/constants.cpp are its rows "minimax-half" and the chosen F.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli.h"
#include "constants_search.h"

using namespace specular::study;

// See specular_study.cpp: the IP's shared library refers to sc_main.
extern "C" int sc_main(int, char**) { return 0; }

int main(int argc, char** argv) {
  specular::cli::Command app{"Searches the constants a (pin 20), h (pin 19, F fraction bits) and the ROM 38 scale s\n"
                             "that minimise max |s*A - 2^-x| over x >= 0 with the peak exact, for h = 1/2 and for\n"
                             "every F = 1 .. N. Deterministic; the global optimum of each grid.",
                             "specular_constants"};
  specular::cli::house_rules(app, "Exit status: 0 done, 1 the search or the CSV file failed, 2 bad usage.");
  std::string out = "constants_search.csv";
  int max_f = 16;
  app.add_option("--out", out, "CSV file for the table")
      ->type_name("FILE")
      ->capture_default_str()
      ->check(specular::cli::file_name());
  app.add_option("--max-f", max_f, "largest F searched")
      ->type_name("N")
      ->capture_default_str()
      ->check(specular::cli::integer_in(1, 24));
  return specular::cli::run(app, argc, argv, [&] {
    try {
      const ConstantsTable table = constants_table(max_f);
      write_constants_csv(table, out);
      const int chosen = table.chosen_f;
      const double best = table.best;
      const auto& rows = table.rows;
      std::printf("search        F  mul6+  h (code/2^F)          a (code/2^22)            s            max error   boxes\n");
      for (const auto& [name, r] : rows) {
        std::printf("%-12s %2d  %4d   %6lld = %-11.9f  %8lld = %-12.9f  %-11.9f  %.9f  %ld%s\n",
                    name.c_str(), r.h_frac_bits, r.h_frac_bits - 1, static_cast<long long>(r.h_code),
                    r.h, static_cast<long long>(r.a_code), r.a, r.s, r.error.worst(), r.boxes,
                    name == "minimax" && r.h_frac_bits == chosen ? "  <- chosen" : "");
      }
      std::printf("best over F <= %d: %.9f; chosen F = %d (fewest bits within 1 %%)\n", max_f, best, chosen);
      // The domain's edge (docs/study.md): no point below it can beat the patent's 0.125.
      std::printf("domain: 0 < h <= %.3f, h/ln2 <= a < 2^%d; below h/ln2 every error is > 2^-e = %.6f\n",
                  search_h_max, search_a_int_bits, std::exp2(-std::exp(1.0)));
      std::printf("table written to %s\n", out.c_str());
    } catch (const std::exception& e) {
      std::cerr << "specular_constants: " << e.what() << "\n";
      return 1;
    }
    return 0;
  });
}
