#include "cli.h"

#include <algorithm>
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

/// CLI11's own messages in the house's words (the tests of bad input match these).
std::string house_message(const CLI::Error& e) {
  const std::string text = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {  // its name may be the app's
    // "The following argument(s) was/were not expected: A B": the first one named.
    const auto list = text.find(": ");
    std::string first = list == std::string::npos ? text : text.substr(list + 2);
    first = first.substr(0, first.find(' '));
    if (first.size() > 1 && first[0] == '-')
      return "unknown option '" + first + "' (see --help)";
    return "unexpected argument '" + first + "' (see --help)";
  }
  // "--out: 1 required TEXT missing": an option at the end of the line without its value.
  const auto colon = text.find(": ");
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) && colon != std::string::npos &&
      text.size() > 8 && text.compare(text.size() - 8, 8, " missing") == 0)
    return "option " + text.substr(0, colon) + " needs a value (see --help)";
  return text;
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

/// Every option's help (and the groups') wrapped to the help's width.
void wrap_help(CLI::App& app) {
  for (CLI::Option* o : app.get_options())
    o->description(wrapped(o->get_description(), help_width - name_column));
  for (CLI::App* group : app.get_subcommands([](CLI::App*) { return true; })) wrap_help(*group);
}

}  // namespace

void house_rules(CLI::App& app, const std::string& footer) {
  app.set_version_flag("--version", app.get_name() + " " + version(), "print the version and exit");
  app.set_help_flag("-h,--help", "print this help and exit");
  app.failure_message([](const CLI::App* a, const CLI::Error& e) {
    return a->get_name() + ": error: " + house_message(e) + "\n";
  });
  app.get_formatter()->column_width(30);
  if (!footer.empty()) app.footer(wrapped(footer, help_width));
}

int run(CLI::App& app, std::vector<std::string> args, const std::function<int()>& body) {
  wrap_help(app);
  try {
    std::reverse(args.begin(), args.end());  // CLI11 takes them last first
    app.parse(args);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version: standard output, status 0
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // the house message on standard error
    return 2;
  } catch (const tb::UsageError& e) {  // an option's callback refused its value
    std::cerr << app.get_name() << ": error: " << e.what() << '\n';
    return 2;
  }
  try {
    return body();
  } catch (const tb::UsageError& e) {
    std::cerr << app.get_name() << ": error: " << e.what() << '\n';
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
