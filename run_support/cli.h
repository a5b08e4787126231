// The one command-line library of specular_tb and the tools: CLI11 with the house rules
// set once. Every executable declares its options on a CLI::App and calls cli::run:
//
//   CLI::App app{"what the tool does", "specular_NAME"};
//   specular::cli::house_rules(app);
//   app.add_option("--count", count, "...")->check(specular::cli::integer_in(1, 100));
//   return specular::cli::run(app, argc, argv, [&] { ...; return 0; });
//
// The rules: --help is built from the declarations, --version prints the project's
// version, and every bad command line (or configuration file, or UsageError thrown by
// the tool) is one line on standard error, "<tool>: error: <option>: <value> is not
// <allowed range or set>", with exit status 2.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "version.h"

namespace specular {
namespace cli {

/// --version, the error spelling, the help's layout; `footer` ends the help (exit
/// statuses, examples).
void house_rules(CLI::App& app, const std::string& footer = "");

/// Parses the command line and runs `body`: --help and --version print and return 0, a
/// bad command line or a UsageError out of `body` prints one line and returns 2;
/// otherwise body's status.
int run(CLI::App& app, int argc, char** argv, const std::function<int()>& body);
/// The same for a tool that already holds its arguments (argv[1..]), printing to `out`
/// (--help, --version) and `err` (the error line).
int run(CLI::App& app, const std::vector<std::string>& args, const std::function<int()>& body,
        std::ostream& out = std::cout, std::ostream& err = std::cerr);

/// Every option's help (and its groups') wrapped to the help's width, 100 columns; a
/// text with line breaks of its own is left as written. run() does it before parsing.
void wrap_help(CLI::App& app);

/// CLI11's message for `e` in the house's words ("unknown option '--x'", "option --out
/// needs a value", "--sweep takes no value (got 'yes')", "option --n is given more than
/// once"); `args`, the command line, to quote a value.
std::string error_text(const CLI::App& app, const CLI::Error& e, const std::vector<std::string>& args);

// Checks of a value as the user typed it, through parse_values.h's strict conversions
// (the whole text or nothing; "010" is ten): the message names the value and the
// allowed range. Integers are rewritten to plain decimal for CLI11's own conversion.

/// A decimal integer in [lo, hi]; `what` names it in the message ("N = 0 is outside
/// ..."), empty: the value alone ("0 is outside ...").
CLI::Validator integer_in(long long lo, long long hi, const std::string& what = "");
/// An unsigned 64-bit decimal integer (a seed, a count).
CLI::Validator unsigned64(const std::string& what = "");
/// A real number in [lo, hi]; `range` as the message shows it (empty: "[lo, hi]").
CLI::Validator real_in(double lo, double hi, const std::string& range = "",
                       const std::string& what = "");
/// One of `names`: "'x' is not one of: a, b, c".
CLI::Validator one_of(const std::vector<std::string>& names, const std::string& what = "");

/// A check through `parse`, one of the project's parsers (parse_shard, parse_constants,
/// ...): the text is good when it does not throw, and its message is the error (a leading
/// "<option>: " or "<option> = " of it dropped, CLI11 names the option).
template <class Parse>
CLI::Validator parsed_by(Parse parse) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
          return {};
        } catch (const std::exception& e) {
          // "--x: why" and "--x = 'v' why" lose their "--x" (CLI11 puts it first).
          const std::string message = e.what();
          const auto blank = message.find(' ');
          if (message.rfind("--", 0) != 0 || blank == std::string::npos) return message;
          if (message[blank - 1] == ':') return message.substr(blank + 1);
          if (message.compare(blank, 3, " = ") == 0) return message.substr(blank + 3);
          return message;
        }
      },
      "");
}

/// An option whose text `parse` turns into `target` (an enum, a shard), checked first by
/// parsed_by(parse).
template <class T, class Parse>
CLI::Option* add_parsed(CLI::App& app, const std::string& name, T& target, Parse parse,
                        const std::string& help) {
  return app
      .add_option_function<std::string>(
          name, [&target, parse](const std::string& text) { target = parse(text); }, help)
      ->check(parsed_by(parse));
}

}  // namespace cli
}  // namespace specular
