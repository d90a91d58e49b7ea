// SPDX-License-Identifier: MIT
#include "world_stage_syntax.hpp"

#include <cctype>

#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/limits/input_limits.hpp"

namespace lookahead::exploration::detail {
namespace {

using slam::ParseError;

struct Token {
  std::string text;
  std::size_t line = 0;
  bool quoted = false;
};

bool is_punct(char c) { return c == '(' || c == ')' || c == '[' || c == ']'; }

// Reads a word; a '[' right after a word character belongs to it (`point[3]`).
std::size_t read_word(const std::string& s, std::size_t i, std::string& out) {
  while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i])) && s[i] != '#' && s[i] != '"' && s[i] != '(' &&
         s[i] != ')' && s[i] != ']') {
    if (s[i] == '[') {
      if (out.empty()) break;
      const std::size_t close = s.find(']', i);
      if (close == std::string::npos) break;
      out += s.substr(i, close - i + 1);
      i = close + 1;
      continue;
    }
    out += s[i++];
  }
  return i;
}

std::vector<Token> tokenize(const std::string& s, const std::string& file) {
  std::vector<Token> tokens;
  std::size_t line = 1;
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (c == '\n') ++line;
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (c == '#') {
      while (i < s.size() && s[i] != '\n') ++i;
      continue;
    }
    if (is_punct(c)) {
      tokens.push_back({std::string(1, c), line, false});
      ++i;
      continue;
    }
    if (c == '"') {
      const std::size_t close = s.find('"', i + 1);
      if (close == std::string::npos || s.find('\n', i + 1) < close) {
        throw ParseError(file, line, "string", s.substr(i, 32), "unterminated string");
      }
      tokens.push_back({s.substr(i + 1, close - i - 1), line, true});
      i = close + 1;
      continue;
    }
    Token t{"", line, false};
    i = read_word(s, i, t.text);
    tokens.push_back(std::move(t));
  }
  return tokens;
}

class Parser {
 public:
  Parser(std::vector<Token> tokens, const std::string& file) : t_(std::move(tokens)), file_(file) {}

  StageFile file() {
    StageFile out;
    StageModel top;
    while (pos_ < t_.size()) entry(top, out, true);
    out.models = std::move(top.children);
    return out;
  }

 private:
  const Token& next(const char* what) {
    if (pos_ >= t_.size()) {
      throw ParseError(file_, t_.empty() ? 0 : t_.back().line, what, "", "unexpected end of file");
    }
    return t_[pos_++];
  }
  bool peek(const char* text) const { return pos_ < t_.size() && !t_[pos_].quoted && t_[pos_].text == text; }

  // Each nested block is a recursion: a bound keeps a deeply nested file from
  // overflowing the stack.
  void body(StageModel& m, StageFile& out) {
    if (++depth_ > slam::limits::kMaxWorldNesting) {
      throw ParseError(file_, m.line, "nesting depth", std::to_string(depth_),
                       "blocks nest deeper than 64 (limits::kMaxWorldNesting)");
    }
    while (!peek(")")) entry(m, out, false);
    ++pos_;
    --depth_;
  }

  void entry(StageModel& parent, StageFile& out, bool top) {
    const Token key = next("key");
    if (key.quoted || is_punct(key.text[0])) {
      throw ParseError(file_, key.line, "key", key.text, "expected a name");
    }
    if (top && key.text == "define") {
      const Token name = next("define name");
      StageDefine d;
      d.parent = next("define parent").text;
      d.body.type = name.text;
      d.body.line = name.line;
      if (next("(").text != "(") throw ParseError(file_, name.line, "define", name.text, "expected '('");
      body(d.body, out);
      out.defines[name.text] = std::move(d);
    } else if (peek("(")) {
      ++pos_;
      StageModel m;
      m.type = key.text;
      m.line = key.line;
      body(m, out);
      parent.children.push_back(std::move(m));
    } else {
      parent.properties[key.text] = value(key);
    }
  }

  StageProperty value(const Token& key) {
    StageProperty p;
    p.line = key.line;
    const Token first = next(key.text.c_str());
    if (first.quoted || first.text != "[") {
      if (!first.quoted && is_punct(first.text[0])) {
        throw ParseError(file_, first.line, key.text, first.text, "expected a value");
      }
      p.values.push_back(first.text);
      return p;
    }
    for (Token v = next(key.text.c_str()); v.quoted || v.text != "]"; v = next(key.text.c_str())) {
      if (!v.quoted && is_punct(v.text[0])) {
        throw ParseError(file_, v.line, key.text, v.text, "unexpected token in a list");
      }
      p.values.push_back(v.text);
    }
    return p;
  }

  std::vector<Token> t_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

StageFile parse_stage_world(const std::string& text, const std::string& file) {
  return Parser(tokenize(text, file), file).file();
}

}  // namespace lookahead::exploration::detail
