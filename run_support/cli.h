// The one command-line library of specular_tb and the tools: CLI11 with the house rules
// set once, behind a small facade. Every executable declares its options on a
// cli::Command and calls cli::run:
//
//   cli::Command app{"what the tool does", "specular_NAME"};
//   specular::cli::house_rules(app);
//   app.add_option("--count", count, "...")->check(specular::cli::integer_in(1, 100));
//   return specular::cli::run(app, argc, argv, [&] { ...; return 0; });
//
// The rules: --help is built from the declarations, --version prints the project's
// version, and every bad command line (or configuration file, or UsageError thrown by
// the tool) is one line on standard error, "<tool>: error: <option>: <value> is not
// <allowed range or set>", with exit status 2.
//
// Why a facade: Debian 12's CLI11 (2.1.2) is header-only, and a file that includes it
// compiles the library again, about 6 CPU-seconds for the header alone (its validators
// are objects defined in every file) and 200 KB of code, in each of the Release, the
// sanitizer and the fuzz builds. Here only cli.cpp includes it; the tools see the names
// they use and nothing else (docs/testing/ci_budget.md).
#pragma once

#include <cstddef>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "usage_error.h"
#include "version.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace specular {
namespace cli {

/// A check of an option's text as the user typed it: `test` returns "" when it is good
/// (and may rewrite it, as integer_in does) or the message; `description` is what the
/// help shows beside the option ("in [1, 100]").
struct Check {
  std::function<std::string(std::string&)> test;
  std::string description;
};

/// One declared option. Its setters return the option, so that they chain as CLI11's do:
/// `app.add_option(...)->type_name("N")->check(...)`.
class Option {
 public:
  explicit Option(CLI::Option* option) : option_(option) {}
  Option* type_name(const std::string& name);  ///< the value's name in the help
  Option* group(const std::string& name);      ///< the help's heading it stands under
  Option* check(const Check& check);
  Option* required();
  Option* capture_default_str();  ///< the help shows the target's value at declaration
  Option* expected(int min, int max);  ///< values per use; max -1: unbounded
  Option* disable_flag_override();     ///< a flag takes no "=value"
  Option* allow_extra_args(bool allow);

 private:
  CLI::Option* option_;
};

/// A command line: the options of one executable (or a group of them, add_option_group).
class Command {
 public:
  Command(const std::string& description, const std::string& name);
  ~Command();
  Command(const Command&) = delete;
  Command& operator=(const Command&) = delete;

  /// An option stored in `target`, converted by CLI11 (the types cli.cpp instantiates:
  /// std::string, int, unsigned, long, long long, unsigned long, unsigned long long,
  /// double, std::vector<std::string>). A name without dashes is a positional argument.
  template <class T>
  Option* add_option(const std::string& name, T& target, const std::string& help);
  /// An option whose value (T: std::string, or std::vector<std::string> for an option
  /// given more than once) is handed to `apply`; a UsageError thrown there is a bad value.
  template <class T>
  Option* add_option_function(const std::string& name, const std::function<void(const T&)>& apply,
                              const std::string& help);
  Option* add_flag(const std::string& name, bool& target, const std::string& help);
  Option* add_flag(const std::string& name, const std::string& help);  ///< count() tells
  /// Options shown under `name`'s heading; with require_option(1), exactly one of them.
  Command* add_option_group(const std::string& name, const std::string& description);
  void require_option(std::size_t exactly);
  /// --config FILE: options read from a TOML or INI file; the command line's win.
  Option* set_config(const std::string& name, const std::string& help);
  /// No --version option (a tool whose --version is a value of its own).
  void disable_version_flag();
  void description(const std::string& text);
  void footer(const std::string& text);

  std::string get_name() const;
  /// Times the option (or positional argument) `name` was given.
  std::size_t count(const std::string& name) const;
  /// Names of every option and positional argument given, in declaration order.
  std::vector<std::string> given() const;
  /// The configuration file named on the command line, "" if none.
  std::string config_file() const;
  std::string help() const;

  /// The library's object (cli.cpp only: the tools never see CLI11's headers).
  CLI::App& impl() { return *app_; }
  const CLI::App& impl() const { return *app_; }

 private:
  explicit Command(CLI::App* group);  // a group, owned by its parent's CLI::App
  Option* keep(CLI::Option* option);

  std::unique_ptr<CLI::App> owned_;  // empty for a group
  CLI::App* app_;
  std::vector<std::unique_ptr<Option>> options_;
  std::vector<std::unique_ptr<Command>> groups_;
};

/// --version, the error spelling, the help's layout; `footer` ends the help (exit
/// statuses, examples).
void house_rules(Command& app, const std::string& footer = "");

/// A command line CLI11 refused, in the house's words ("unknown option '--x' (see
/// --help)", "option --out needs a value (see --help)", "--sweep takes no value (got
/// 'yes')", "option --n is given more than once", "--n: 0 is outside ...").
class CommandLineError : public tb::UsageError {
 public:
  CommandLineError(const std::string& text, bool missing_required)
      : tb::UsageError(text), missing_required_(missing_required) {}
  /// A required option or argument was not given.
  bool missing_required() const { return missing_required_; }

 private:
  bool missing_required_;
};

enum class Parsed { run, help, version };
/// Parses `args` (argv[1..]) for a caller that reports on its own: help or version asked,
/// or run. A bad command line throws CommandLineError; a UsageError out of an option's
/// function passes through as it is.
Parsed parse(Command& app, const std::vector<std::string>& args);

/// Parses the command line and runs `body`: --help and --version print and return 0, a
/// bad command line or a UsageError out of `body` prints one line and returns 2;
/// otherwise body's status.
int run(Command& app, int argc, char** argv, const std::function<int()>& body);
/// The same for a tool that already holds its arguments (argv[1..]), printing to `out`
/// (--help, --version) and `err` (the error line).
int run(Command& app, const std::vector<std::string>& args, const std::function<int()>& body,
        std::ostream& out = std::cout, std::ostream& err = std::cerr);

// Checks of a value as the user typed it, through parse_values.h's strict conversions
// (the whole text or nothing; "010" is ten): the message names the value and the
// allowed range. Integers are rewritten to plain decimal for CLI11's own conversion.

/// A decimal integer in [lo, hi]; `what` names it in the message ("N = 0 is outside
/// ..."), empty: the value alone ("0 is outside ...").
Check integer_in(long long lo, long long hi, const std::string& what = "");
/// An unsigned 64-bit decimal integer (a seed, a count).
Check unsigned64(const std::string& what = "");
/// A real number in [lo, hi]; `range` as the message shows it (empty: "[lo, hi]").
Check real_in(double lo, double hi, const std::string& range = "", const std::string& what = "");
/// One of `names`: "'x' is not one of: a, b, c".
Check one_of(const std::vector<std::string>& names, const std::string& what = "");
/// A file name that is not empty: "the file name is empty".
Check file_name();

/// `message` without a leading "<option>: " or "<option> = " (CLI11 names the option).
std::string without_option_name(const std::string& message);

/// A check through `parse`, one of the project's parsers (parse_shard, parse_constants,
/// ...): the text is good when it does not throw, and its message is the error.
template <class Parse>
Check parsed_by(Parse parse) {
  return Check{[parse](std::string& text) -> std::string {
                 try {
                   parse(text);
                   return {};
                 } catch (const std::exception& e) {
                   return without_option_name(e.what());
                 }
               },
               ""};
}

/// An option whose text `parse` turns into `target` (an enum, a shard), checked first by
/// parsed_by(parse).
template <class T, class Parse>
Option* add_parsed(Command& app, const std::string& name, T& target, Parse parse, const std::string& help) {
  return app
      .add_option_function<std::string>(
          name, [&target, parse](const std::string& text) { target = parse(text); }, help)
      ->check(parsed_by(parse));
}

}  // namespace cli
}  // namespace specular
