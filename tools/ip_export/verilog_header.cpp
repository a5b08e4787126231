#include "verilog_header.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace specular {
namespace ip_export {
namespace {

struct Token {
  enum Kind { identifier, number, string, symbol, end } kind;
  std::string text;
  int line;
};

/// Identifiers (with `$` and `` ` `` directives), decimal numbers (sized literals are
/// refused where a value is needed), string literals, single-character symbols.
/// Comments and attributes `(* *)` are skipped.
std::vector<Token> tokenise(const std::string& text, const std::string& path) {
  std::vector<Token> tokens;
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n) {
    const char c = text[i];
    if (c == '\n') { ++line; ++i; continue; }
    if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
    if (c == '/' && i + 1 < n && text[i + 1] == '/') {
      while (i < n && text[i] != '\n') ++i;
      continue;
    }
    if (c == '/' && i + 1 < n && text[i + 1] == '*') {
      const std::size_t e = text.find("*/", i + 2);
      if (e == std::string::npos) throw VerilogError(path + ":" + std::to_string(line) + ": unterminated comment");
      line += static_cast<int>(std::count(text.begin() + static_cast<long>(i), text.begin() + static_cast<long>(e), '\n'));
      i = e + 2;
      continue;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$' || c == '`') {
      std::size_t j = i + 1;
      while (j < n && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_' || text[j] == '$')) ++j;
      tokens.push_back({Token::identifier, text.substr(i, j - i), line});
      i = j;
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t j = i + 1;
      // A sized or based literal (8'hFF) stays one token: its ' and the digits after.
      while (j < n && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_' || text[j] == '\'')) ++j;
      tokens.push_back({Token::number, text.substr(i, j - i), line});
      i = j;
      continue;
    }
    if (c == '"') {
      std::size_t j = i + 1;
      while (j < n && text[j] != '"' && text[j] != '\n') ++j;
      if (j >= n || text[j] != '"') throw VerilogError(path + ":" + std::to_string(line) + ": unterminated string");
      tokens.push_back({Token::string, text.substr(i + 1, j - i - 1), line});
      i = j + 1;
      continue;
    }
    tokens.push_back({Token::symbol, std::string(1, c), line});
    ++i;
  }
  tokens.push_back({Token::end, "", line});
  return tokens;
}

/// Recursive descent over the tokens of one module header.
class HeaderParser {
 public:
  HeaderParser(std::vector<Token> tokens, std::string path,
               std::map<std::string, std::int64_t> overrides = {})
      : tokens_(std::move(tokens)), path_(std::move(path)), overrides_(std::move(overrides)) {}

  VerilogModule parse() {
    VerilogModule m;
    m.file = path_;
    while (!at_end() && !is_identifier("module")) ++pos_;
    expect_identifier("module");
    m.name = identifier("a module name");
    if (accept_symbol("#")) parameter_list(m);
    expect_symbol("(");
    if (!accept_symbol(")")) port_list(m);
    expect_symbol(";");
    return m;
  }

 private:
  const Token& peek() const { return tokens_[pos_]; }
  bool at_end() const { return peek().kind == Token::end; }
  bool is_identifier(const char* word) const {
    return peek().kind == Token::identifier && peek().text == word;
  }
  bool is_symbol(const char* s) const { return peek().kind == Token::symbol && peek().text == s; }
  bool accept_symbol(const char* s) {
    if (!is_symbol(s)) return false;
    ++pos_;
    return true;
  }
  bool accept_identifier(const char* word) {
    if (!is_identifier(word)) return false;
    ++pos_;
    return true;
  }
  [[noreturn]] void fail(const std::string& expected) const {
    throw VerilogError(path_ + ":" + std::to_string(peek().line) + ": expected " + expected +
                       ", found '" + (at_end() ? std::string("end of file") : peek().text) + "'");
  }
  void expect_symbol(const char* s) {
    if (!accept_symbol(s)) fail(std::string("'") + s + "'");
  }
  void expect_identifier(const char* word) {
    if (!accept_identifier(word)) fail(std::string("'") + word + "'");
  }
  std::string identifier(const char* what) {
    if (peek().kind != Token::identifier) fail(what);
    return tokens_[pos_++].text;
  }

  // ---- constant expressions: + - * / on integers and the parameters read so far ----
  std::int64_t expression() {
    std::int64_t v = term();
    while (is_symbol("+") || is_symbol("-")) {
      const bool plus = tokens_[pos_++].text == "+";
      const std::int64_t r = term();
      v = plus ? v + r : v - r;
    }
    return v;
  }
  std::int64_t term() {
    std::int64_t v = factor();
    while (is_symbol("*") || is_symbol("/")) {
      const bool times = tokens_[pos_++].text == "*";
      const std::int64_t r = factor();
      if (!times && r == 0) fail("a non-zero divisor");
      v = times ? v * r : v / r;
    }
    return v;
  }
  std::int64_t factor() {
    if (accept_symbol("(")) {
      const std::int64_t v = expression();
      expect_symbol(")");
      return v;
    }
    if (accept_symbol("-")) return -factor();
    if (peek().kind == Token::number) {
      const std::string text = tokens_[pos_].text;
      if (text.find('\'') != std::string::npos) fail("a plain decimal number");
      ++pos_;
      return std::stoll(text);
    }
    if (peek().kind == Token::identifier) {
      const std::string name = tokens_[pos_].text;
      const auto it = values_.find(name);
      if (it == values_.end()) fail("a parameter declared before");
      ++pos_;
      return it->second;
    }
    fail("a number, a parameter or '('");
  }
  /// `[msb:lsb]`, evaluated; the msb's tokens, spaced, in `msb_text` when one names a
  /// parameter.
  std::pair<std::int64_t, std::int64_t> range(std::string* msb_text = nullptr) {
    expect_symbol("[");
    const std::size_t first = pos_;
    const std::int64_t msb = expression();
    if (msb_text != nullptr) {
      msb_text->clear();
      bool names_parameter = false;
      for (std::size_t i = first; i < pos_; ++i) {
        names_parameter = names_parameter || tokens_[i].kind == Token::identifier;
        *msb_text += (i == first ? "" : " ") + tokens_[i].text;
      }
      if (!names_parameter) msb_text->clear();
    }
    expect_symbol(":");
    const std::int64_t lsb = expression();
    expect_symbol("]");
    return {msb, lsb};
  }

  // ---- #( parameter [range] NAME = value, NAME = value, parameter ... ) ----
  void parameter_list(VerilogModule& m) {
    expect_symbol("(");
    if (accept_symbol(")")) return;
    expect_identifier("parameter");
    int width = 0;
    for (;;) {
      if (is_symbol("[")) {
        const auto r = range();
        width = static_cast<int>(r.first - r.second + 1);
      }
      VerilogParameter p;
      p.name = identifier("a parameter name");
      p.width = width;
      expect_symbol("=");
      if (peek().kind == Token::string) {
        p.is_string = true;
        p.text = tokens_[pos_++].text;
      } else {
        p.value = expression();
        const auto set = overrides_.find(p.name);
        if (set != overrides_.end()) {
          p.value = set->second;
          overrides_.erase(set);
        }
        values_[p.name] = p.value;
      }
      m.parameters.push_back(p);
      if (accept_symbol(")")) return;
      expect_symbol(",");
      if (accept_identifier("parameter")) width = 0;  // a new declaration: its own range
    }
  }

  // ---- ( input wire signed [range] a, b, output reg [range] c ) ----
  void port_list(VerilogModule& m) {
    std::string direction;
    bool is_signed = false, is_vector = false;
    std::pair<std::int64_t, std::int64_t> bits{0, 0};
    std::string msb_text;
    for (;;) {
      if (is_identifier("input") || is_identifier("output") || is_identifier("inout")) {
        const std::string word = tokens_[pos_++].text;
        direction = word == "input" ? "in" : word == "output" ? "out" : "inout";
        accept_identifier("wire") || accept_identifier("reg") || accept_identifier("logic");
        is_signed = accept_identifier("signed");
        is_vector = is_symbol("[");
        msb_text.clear();
        bits = is_vector ? range(&msb_text) : std::make_pair<std::int64_t, std::int64_t>(0, 0);
      } else if (direction.empty()) {
        fail("'input' or 'output'");
      }
      VerilogPort p;
      p.name = identifier("a port name");
      p.direction = direction;
      p.is_signed = is_signed;
      p.is_vector = is_vector;
      p.msb = static_cast<int>(bits.first);
      p.lsb = static_cast<int>(bits.second);
      p.msb_expression = msb_text;
      m.ports.push_back(p);
      if (accept_symbol(")")) return;
      expect_symbol(",");
    }
  }

  std::vector<Token> tokens_;
  std::string path_;
  std::size_t pos_ = 0;
  std::map<std::string, std::int64_t> values_;
  std::map<std::string, std::int64_t> overrides_;  ///< the ones not yet used

 public:
  const std::map<std::string, std::int64_t>& unused_overrides() const { return overrides_; }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw VerilogError("cannot read '" + path + "'");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

VerilogModule read_module_header(const std::string& path,
                                 const std::map<std::string, std::int64_t>& overrides) {
  HeaderParser parser(tokenise(slurp(path), path), path, overrides);
  VerilogModule m = parser.parse();
  if (!parser.unused_overrides().empty()) {
    std::string names;
    for (const auto& p : m.parameters)
      if (!p.is_string) names += (names.empty() ? "" : ", ") + p.name;
    throw VerilogError(path + ": " + m.name + " has no integer parameter '" +
                       parser.unused_overrides().begin()->first + "' (it has " + names + ")");
  }
  return m;
}

std::map<std::string, VerilogModule> read_modules(const std::vector<std::string>& dirs) {
  std::vector<std::string> paths;
  for (const std::string& dir : dirs) {
    std::error_code error;
    if (!std::filesystem::is_directory(dir, error))
      throw VerilogError("'" + dir + "' is not a folder (--source-dir names the source tree, whose rtl/ holds the Verilog)");
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.is_regular_file() && entry.path().extension() == ".v") paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  // Only the name of each file's module and the identifiers after it: the closure needs
  // no header (the variants' headers need not be in the subset read_module_header takes).
  std::map<std::string, VerilogModule> modules;
  std::map<std::string, std::vector<std::string>> words;  // module -> identifiers after its name
  for (const std::string& path : paths) {
    const std::vector<Token> tokens = tokenise(slurp(path), path);
    std::size_t i = 0;
    while (tokens[i].kind != Token::end && !(tokens[i].kind == Token::identifier && tokens[i].text == "module")) ++i;
    if (tokens[i].kind == Token::end || tokens[i + 1].kind != Token::identifier)
      throw VerilogError(path + ": no 'module NAME' in the file");
    VerilogModule m;
    m.name = tokens[i + 1].text;
    m.file = path;
    if (modules.count(m.name))
      throw VerilogError(path + ": module '" + m.name + "' is also in " + modules[m.name].file);
    for (std::size_t j = i + 2; j < tokens.size(); ++j)
      if (tokens[j].kind == Token::identifier) words[m.name].push_back(tokens[j].text);
    modules[m.name] = m;
  }
  for (auto& entry : modules)
    for (const std::string& word : words[entry.first])
      if (word != entry.first && modules.count(word)) entry.second.instantiates.insert(word);
  return modules;
}

std::vector<std::string> file_closure(const std::map<std::string, VerilogModule>& modules,
                                      const std::string& top) {
  std::set<std::string> seen;
  std::vector<std::string> stack{top};
  while (!stack.empty()) {
    const std::string name = stack.back();
    stack.pop_back();
    if (!seen.insert(name).second) continue;
    const auto it = modules.find(name);
    if (it == modules.end()) throw VerilogError("module '" + name + "' is in no file read");
    for (const std::string& child : it->second.instantiates) stack.push_back(child);
  }
  std::vector<std::string> files;
  for (const std::string& name : seen) files.push_back(modules.at(name).file);
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace ip_export
}  // namespace specular
