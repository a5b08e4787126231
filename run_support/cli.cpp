#include "cli.h"

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

}  // namespace

void wrap_help(CLI::App& app) {
  for (CLI::Option* o : app.get_options())
    o->description(wrapped(o->get_description(), help_width - name_column));
  for (CLI::App* group : app.get_subcommands([](CLI::App*) { return true; })) wrap_help(*group);
}

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

void house_rules(CLI::App& app, const std::string& footer) {
  app.set_version_flag("--version", app.get_name() + " " + version(), "print the version and exit");
  app.set_help_flag("-h,--help", "print this help and exit");
  app.get_formatter()->column_width(name_column);
  app.allow_config_extras(CLI::config_extras_mode::error);  // a misspelt key is an error, not ignored
  if (!footer.empty()) app.footer(wrapped(footer, help_width));
}

int run(CLI::App& app, const std::vector<std::string>& args, const std::function<int()>& body,
        std::ostream& out, std::ostream& err) {
  wrap_help(app);
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    app.parse(reversed);
  } catch (const CLI::Success& e) {
    return app.exit(e, out, err);  // --help, --version: status 0
  } catch (const CLI::ParseError& e) {
    err << app.get_name() << ": error: " << error_text(app, e, args) << '\n';
    return 2;
  } catch (const tb::UsageError& e) {  // an option's callback refused its value
    err << app.get_name() << ": error: " << e.what() << '\n';
    return 2;
  }
  try {
    return body();
  } catch (const tb::UsageError& e) {
    err << app.get_name() << ": error: " << e.what() << '\n';
    return 2;
  }
}

int run(CLI::App& app, int argc, char** argv, const std::function<int()>& body) {
  return run(app, std::vector<std::string>(argv + 1, argv + argc), body);
}

CLI::Validator integer_in(long long lo, long long hi, const std::string& what) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  const std::string lead = what.empty() ? "" : what + " = ";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        try {
          const long long value = tb::parse_integer(text, what.empty() ? "value" : what, range);
          if (value < lo || value > hi) return lead + text + " is outside the allowed range " + range;
          text = std::to_string(value);
          return {};
        } catch (const tb::UsageError&) {
          return lead + "'" + text + "' is not an integer; allowed range " + range;
        }
      },
      "in " + range);
}

CLI::Validator unsigned64(const std::string& what) {
  const std::string range = "[0, 18446744073709551615]";
  const std::string lead = what.empty() ? "" : what + " = ";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        try {
          text = std::to_string(tb::parse_unsigned64(text, "value"));
          return {};
        } catch (const tb::UsageError&) {
          return lead + "'" + text + "' is not a whole number in " + range;
        }
      },
      "in [0, 2^64-1]");
}

CLI::Validator real_in(double lo, double hi, const std::string& range_text, const std::string& what) {
  const std::string range = range_text.empty() ? "[" + number(lo) + ", " + number(hi) + "]" : range_text;
  const std::string lead = what.empty() ? "" : what + " = ";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
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
      "in " + range);
}

CLI::Validator one_of(const std::vector<std::string>& names, const std::string& what) {
  const std::string lead = what.empty() ? "" : what + " ";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        for (const std::string& n : names)
          if (text == n) return {};
        return lead + "'" + text + "' is not one of: " + joined(names);
      },
      joined(names));
}

}  // namespace cli
}  // namespace specular
