// specular_progress DONE TOTAL SECONDS [UNIT [LABEL]]: prints progress_line() (progress.h)
// on standard output, for scripts whose long runs report progress the way specular_tb
// does (scripts/flows/gatelevel/gatesim.sh; the script decides whether standard error is a terminal).
// Exit 2 with a message naming the bad value and the allowed range (cli.h).
#include <cstdint>
#include <iostream>
#include <string>

#include "cli.h"
#include "progress.h"

int main(int argc, char** argv) {
  specular::cli::Command app{"Prints the progress line of every long run (run_support/progress.h) on standard output.",
                             "specular_progress"};
  specular::cli::house_rules(app);
  std::uint64_t done = 0, total = 0;
  double seconds = 0;
  std::string unit = "operations", label;
  app.add_option("DONE", done, "operations done")->required()->check(specular::cli::unsigned64());
  app.add_option("TOTAL", total, "operations in all")->required()->check(specular::cli::unsigned64());
  app.add_option("SECONDS", seconds, "time since the start, in seconds")
      ->required()
      ->check(specular::cli::real_in(0, 1e9, "from 0 to 1e9"));
  app.add_option("UNIT", unit, "what is counted")->capture_default_str();
  app.add_option("LABEL", label, "the line's name (none by default)");
  return specular::cli::run(app, argc, argv, [&] {
    std::cout << specular::tb::progress_line(done, total, seconds, unit, label) << "\n";
    return 0;
  });
}
