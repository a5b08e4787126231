#include "cli.h"

#include <CLI/CLI.hpp>
#include <iostream>
#include <sstream>

#include "parse_values.h"
#include "usage_error.h"

namespace specular {
namespace cli {

const char* version() { return SPECULAR_VERSION; }

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

std::string number(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

constexpr std::size_t help_width = 100, name_column = 30;

/// `text` broken at blanks into lines of at most `width` characters; a text that
/// already has its own line breaks is left as written.
std::string wrapped(const std::string& text, std::size_t width) {
  if (text.find('\n') != std::string::npos) return text;
  std::string out, line, word;
  std::istringstream words(text);
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

/// Every option's help (and its groups') wrapped to the help's width, 100 columns; a
/// text with line breaks of its own is left as written. Done before parsing and help().
void wrap_help(CLI::App& app) {
  for (CLI::Option* o : app.get_options())
    o->description(wrapped(o->get_description(), help_width - name_column));
  for (CLI::App* group : app.get_subcommands([](CLI::App*) { return true; })) wrap_help(*group);
}

/// CLI11's message for `e` in the house's words; `args`, the command line, to quote a value.
std::string error_text(const CLI::App& app, const CLI::Error& e, const std::vector<std::string>& args) {
  const std::string text = e.what();
  const auto colon = text.find(": ");
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {  // its get_name() may be the app's
    // "The following argument(s) was/were not expected: B A": the first one named (the
    // list is in reverse).
    std::string first = colon == std::string::npos ? text : text.substr(colon + 2);
    first = first.substr(first.rfind(' ') == std::string::npos ? 0 : first.rfind(' ') + 1);
    const bool positionals = !app.get_options([](const CLI::Option* o) { return o->get_positional(); }).empty();
    if ((first.size() > 1 && first[0] == '-') || !positionals)
      return "unknown option '" + first + "' (see --help)";
    return "unexpected argument '" + first + "' (see --help)";
  }
  const std::string extra_key = "INI was not able to parse ";
  if (dynamic_cast<const CLI::ConfigError*>(&e) && text.rfind(extra_key, 0) == 0)
    return "--config: '" + text.substr(extra_key.size()) + "' in the file is not an option (see --help)";
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
    const auto ends = [&](const std::string& tail) {
      return text.size() > tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
    };
    // "--out: 1 required TEXT missing": an option at the end of the line without its value.
    if (colon != std::string::npos && ends(" missing"))
      return "option " + text.substr(0, colon) + " needs a value (see --help)";
    // "--sweep was given a disallowed flag override": --sweep=yes.
    const std::string override_tail = " was given a disallowed flag override";
    if (ends(override_tail)) {
      std::string name = text.substr(0, text.size() - override_tail.size());
      if (name.rfind('-', 0) != 0) name = "--" + name;  // CLI11 names the flag without its dashes
      std::string value;
      for (const std::string& a : args)
        if (a.rfind(name + "=", 0) == 0) value = a.substr(name.size() + 1);
      return name + " takes no value (got '" + value + "')";
    }
    // "--n: At Most 1 required but received 2": given twice.
    if (colon != std::string::npos && text.find("At Most 1 required", colon) != std::string::npos)
      return "option " + text.substr(0, colon) + " is given more than once";
  }
  return text;
}

}  // namespace

// ---- Option ----

Option* Option::type_name(const std::string& name) {
  option_->type_name(name);
  return this;
}
Option* Option::group(const std::string& name) {
  option_->group(name);
  return this;
}
Option* Option::check(const Check& check) {
  option_->check(CLI::Validator(check.test, check.description));
  return this;
}
Option* Option::required() {
  option_->required();
  return this;
}
Option* Option::capture_default_str() {
  option_->capture_default_str();
  return this;
}
Option* Option::expected(int min, int max) {
  option_->expected(min, max);
  return this;
}
Option* Option::disable_flag_override() {
  option_->disable_flag_override();
  return this;
}
Option* Option::allow_extra_args(bool allow) {
  option_->allow_extra_args(allow);
  return this;
}

// ---- Command ----

Command::Command(const std::string& description, const std::string& name)
    : owned_(std::make_unique<CLI::App>(description, name)), app_(owned_.get()) {}
Command::Command(CLI::App* group) : app_(group) {}
Command::~Command() = default;

Option* Command::keep(CLI::Option* option) {
  options_.push_back(std::make_unique<Option>(option));
  return options_.back().get();
}

template <class T>
Option* Command::add_option(const std::string& name, T& target, const std::string& help) {
  return keep(app_->add_option(name, target, help));
}
// The target types the tools use; another one is a link error naming it.
template Option* Command::add_option(const std::string&, std::string&, const std::string&);
template Option* Command::add_option(const std::string&, int&, const std::string&);
template Option* Command::add_option(const std::string&, unsigned&, const std::string&);
template Option* Command::add_option(const std::string&, long&, const std::string&);
template Option* Command::add_option(const std::string&, long long&, const std::string&);
template Option* Command::add_option(const std::string&, unsigned long&, const std::string&);
template Option* Command::add_option(const std::string&, unsigned long long&, const std::string&);
template Option* Command::add_option(const std::string&, double&, const std::string&);
template Option* Command::add_option(const std::string&, std::vector<std::string>&, const std::string&);

template <class T>
Option* Command::add_option_function(const std::string& name, const std::function<void(const T&)>& apply,
                                     const std::string& help) {
  return keep(app_->add_option_function<T>(name, apply, help));
}
template Option* Command::add_option_function(const std::string&, const std::function<void(const std::string&)>&,
                                              const std::string&);
template Option* Command::add_option_function(const std::string&,
                                              const std::function<void(const std::vector<std::string>&)>&,
                                              const std::string&);

Option* Command::add_flag(const std::string& name, bool& target, const std::string& help) {
  return keep(app_->add_flag(name, target, help));
}
Option* Command::add_flag(const std::string& name, const std::string& help) {
  return keep(app_->add_flag(name, help));
}

Command* Command::add_option_group(const std::string& name, const std::string& description) {
  groups_.push_back(std::unique_ptr<Command>(new Command(app_->add_option_group(name, description))));
  return groups_.back().get();
}
void Command::require_option(std::size_t exactly) { app_->require_option(exactly); }

Option* Command::set_config(const std::string& name, const std::string& help) {
  return keep(app_->set_config(name, "", help));
}
void Command::disable_version_flag() { app_->set_version_flag(""); }
void Command::description(const std::string& text) { app_->description(text); }
void Command::footer(const std::string& text) { app_->footer(wrapped(text, help_width)); }

std::string Command::get_name() const { return app_->get_name(); }
std::size_t Command::count(const std::string& name) const { return app_->count(name); }
std::vector<std::string> Command::given() const {
  std::vector<std::string> names;
  for (const CLI::Option* o : app_->get_options())
    if (o->count() > 0) names.push_back(o->get_name());
  return names;
}
std::string Command::config_file() const {
  const CLI::Option* config = app_->get_config_ptr();
  return config == nullptr ? std::string() : config->as<std::string>();
}
std::string Command::help() const {
  wrap_help(*app_);
  return app_->help();
}

// ---- the house rules ----

void house_rules(Command& command, const std::string& footer) {
  CLI::App& app = command.impl();
  app.set_version_flag("--version", app.get_name() + " " + version(), "print the version and exit");
  app.set_help_flag("-h,--help", "print this help and exit");
  app.get_formatter()->column_width(name_column);
  app.allow_config_extras(CLI::config_extras_mode::error);  // a misspelt key is an error, not ignored
  if (!footer.empty()) command.footer(footer);
}

Parsed parse(Command& command, const std::vector<std::string>& args) {
  CLI::App& app = command.impl();
  wrap_help(app);
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    return Parsed::help;
  } catch (const CLI::CallForAllHelp&) {
    return Parsed::help;
  } catch (const CLI::CallForVersion&) {
    return Parsed::version;
  } catch (const CLI::ParseError& e) {
    throw CommandLineError(error_text(app, e, args), dynamic_cast<const CLI::RequiredError*>(&e) != nullptr);
  }
  return Parsed::run;
}

int run(Command& command, const std::vector<std::string>& args, const std::function<int()>& body,
        std::ostream& out, std::ostream& err) {
  try {
    switch (parse(command, args)) {
      case Parsed::help:
        out << command.help();
        return 0;
      case Parsed::version:
        out << command.get_name() << ' ' << version() << '\n';
        return 0;
      case Parsed::run:
        break;
    }
    return body();
  } catch (const tb::UsageError& e) {  // a bad command line, a value an option's function or the body refused
    err << command.get_name() << ": error: " << e.what() << '\n';
    return 2;
  }
}

int run(Command& command, int argc, char** argv, const std::function<int()>& body) {
  return run(command, std::vector<std::string>(argv + 1, argv + argc), body);
}

// ---- checks ----

std::string without_option_name(const std::string& message) {
  // "--x: why" and "--x = 'v' why" lose their "--x" (CLI11 puts it first).
  const auto blank = message.find(' ');
  if (message.rfind("--", 0) != 0 || blank == std::string::npos) return message;
  if (message[blank - 1] == ':') return message.substr(blank + 1);
  if (message.compare(blank, 3, " = ") == 0) return message.substr(blank + 3);
  return message;
}

Check integer_in(long long lo, long long hi, const std::string& what) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  const std::string lead = what.empty() ? "" : what + " = ";
  return Check{[=](std::string& text) -> std::string {
                 try {
                   const long long value = tb::parse_integer(text, what.empty() ? "value" : what, range);
                   if (value < lo || value > hi) return lead + text + " is outside the allowed range " + range;
                   text = std::to_string(value);
                   return {};
                 } catch (const tb::UsageError&) {
                   return lead + "'" + text + "' is not an integer; allowed range " + range;
                 }
               },
               "in " + range};
}

Check unsigned64(const std::string& what) {
  const std::string range = "[0, 18446744073709551615]";
  const std::string lead = what.empty() ? "" : what + " = ";
  return Check{[=](std::string& text) -> std::string {
                 try {
                   text = std::to_string(tb::parse_unsigned64(text, "value"));
                   return {};
                 } catch (const tb::UsageError&) {
                   return lead + "'" + text + "' is not a whole number in " + range;
                 }
               },
               "in [0, 2^64-1]"};
}

Check real_in(double lo, double hi, const std::string& range_text, const std::string& what) {
  const std::string range = range_text.empty() ? "[" + number(lo) + ", " + number(hi) + "]" : range_text;
  const std::string lead = what.empty() ? "" : what + " = ";
  return Check{[=](std::string& text) -> std::string {
                 double value = 0;
                 try {
                   value = tb::parse_real(text, "value", range);
                 } catch (const tb::UsageError&) {
                   return lead + "'" + text + "' is not a number; allowed range " + range;
                 }
                 if (!(value >= lo && value <= hi))  // NaN fails both
                   return lead + text + " is outside the allowed range " + range;
                 return {};
               },
               "in " + range};
}

Check one_of(const std::vector<std::string>& names, const std::string& what) {
  const std::string lead = what.empty() ? "" : what + " ";
  return Check{[=](std::string& text) -> std::string {
                 for (const std::string& n : names)
                   if (text == n) return {};
                 return lead + "'" + text + "' is not one of: " + joined(names);
               },
               joined(names)};
}

Check file_name() {
  return Check{[](std::string& text) { return text.empty() ? std::string("the file name is empty") : std::string(); },
               ""};
}

}  // namespace cli
}  // namespace specular
