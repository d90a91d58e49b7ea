// SPDX-License-Identifier: MIT
#include "lookahead/slam/config/yaml_sections.hpp"

#include <cctype>
#include <fstream>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam::config {

void fail_at(const std::string& source, const YAML::Node& node, const std::string& key, const std::string& why) {
  throw ParseError(source, static_cast<std::size_t>(node.Mark().line + 1), key, node.IsScalar() ? node.Scalar() : "",
                   why);
}

YAML::Node parse_sections(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw ParseError(source, static_cast<std::size_t>(e.mark.line + 1), "", "", e.msg);
  }
  if (!root.IsNull() && !root.IsMap()) throw ParseError(source, 1, "", "", "top level must be a map of sections");
  return root;
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, "", "", "cannot open file");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void SectionLoader::section(const char* name) {
  // reset(), not operator=: assigning to a yaml-cpp Node writes through to the node it
  // refers to (the previous section) instead of rebinding.
  current_.reset(root_[name]);
  name_ = name;
  if (current_ && !current_.IsMap()) fail_at(source_, current_, name, "must be a map");
  if (current_) seen_sections_.insert(name);
}

YAML::Node SectionLoader::node(const char* key) {
  if (!current_) return YAML::Node(YAML::NodeType::Undefined);  // Node() would be a null value
  const YAML::Node n = current_[key];
  if (n) seen_keys_.insert(name_ + "." + key);
  return n;
}

void SectionLoader::reject_unknown(const std::set<std::string>& skip) const {
  for (const auto& s : root_) {
    const std::string sec = s.first.as<std::string>();
    if (skip.count(sec)) continue;
    if (!seen_sections_.count(sec)) fail_at(source_, s.first, sec, "unknown section");
    for (const auto& k : s.second) {
      const std::string key = sec + "." + k.first.as<std::string>();
      if (!seen_keys_.count(key)) fail_at(source_, k.first, key, "unknown key");
    }
  }
}

namespace {

bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

// Where `name` first occurs in `text` as a whole name (not inside a longer one), or npos.
std::size_t find_name(const std::string& text, const std::string& name) {
  for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    const bool starts = at == 0 || !name_char(text[at - 1]);
    const std::size_t end = at + name.size();
    const bool ends = end == text.size() || !name_char(text[end]) ||
                      (text[end] == '.' && (end + 1 == text.size() || !name_char(text[end + 1])));
    if (starts && ends) return at;
  }
  return std::string::npos;
}

}  // namespace

void SectionLoader::fail_impossible(const std::string& why) const {
  const std::string reason = "impossible value: " + why;
  std::size_t first = std::string::npos;
  YAML::Node where;
  std::string field;
  for (const auto& s : root_) {
    const std::string sec = s.first.as<std::string>();
    if (!seen_sections_.count(sec)) continue;
    for (const auto& k : s.second) {
      const std::string key = k.first.as<std::string>();
      std::size_t at = find_name(why, sec + "." + key);
      if (at == std::string::npos) at = find_name(why, key);
      if (at < first) first = at, where.reset(k.second), field = sec + "." + key;
    }
  }
  if (first == std::string::npos) throw ParseError(source_, 0, "", "", reason);
  fail_at(source_, where, field, reason);
}

}  // namespace lookahead::slam::config
