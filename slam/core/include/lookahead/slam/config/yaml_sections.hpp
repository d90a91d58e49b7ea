// SPDX-License-Identifier: MIT
// The machinery every lookahead YAML loader shares. A library lists its keys once, as a
// visitor over (section, key, field, doc); SectionLoader reads a file through that list
// (rejecting unknown sections and keys, errors naming file:line, key and value) and
// SectionDumper prints it back with a comment per key. Enums with a name table
// (named_choice.hpp) are read and printed by name.
#pragma once

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "lookahead/slam/config/named_choice.hpp"

namespace lookahead::slam::config {

[[noreturn]] void fail_at(const std::string& source, const YAML::Node& node, const std::string& key,
                          const std::string& why);

/// Parses YAML text; syntax errors become ParseError(source, line). A null document is
/// allowed (an empty file); anything else must be a map of sections.
YAML::Node parse_sections(const std::string& text, const std::string& source);

/// The whole text of a file; ParseError when it cannot be opened.
std::string read_text_file(const std::string& path);

class SectionLoader {
 public:
  SectionLoader(const YAML::Node& root, std::string source) : root_(root), source_(std::move(source)) {}
  void section(const char* name);
  template <typename T>
  void operator()(const char* key, T& field, const char* /*doc*/) {
    const YAML::Node n = node(key);
    if (!n) return;
    if constexpr (is_named_choice_v<T>) {
      const auto v = choice_from_name<T>(n.IsScalar() ? n.Scalar() : "");
      if (!v) fail_at(source_, n, name_ + "." + key, "bad value: expected " + choice_list<T>());
      field = *v;
    } else {
      try {
        field = n.as<T>();
      } catch (const YAML::Exception&) {
        fail_at(source_, n, name_ + "." + key, "bad value");
      }
    }
  }
  /// Every section and key of the document must have been visited (`skip`: sections
  /// another loader reads).
  void reject_unknown(const std::set<std::string>& skip = {}) const;
  /// Throws the ParseError of an impossible value that the options' own validation found:
  /// `why` names the option ("section.key ..." or "key ..."); the error carries the line
  /// and value of the first key it names that this document sets (line 0 if none).
  [[noreturn]] void fail_impossible(const std::string& why) const;

 protected:
  /// The key's node in the current section (undefined when absent), marked as seen.
  YAML::Node node(const char* key);
  [[nodiscard]] const std::string& source() const { return source_; }
  [[nodiscard]] const std::string& section_name() const { return name_; }

 private:
  YAML::Node root_, current_;
  std::string source_, name_;
  std::set<std::string> seen_sections_, seen_keys_;
};

/// Collects the names of the sections a key list opens (which sections a loader reads).
struct SectionNames {
  std::set<std::string> names;
  void section(const char* name) { names.insert(name); }
  template <typename T>
  void operator()(const char* /*key*/, const T& /*field*/, const char* /*doc*/) {}
};

class SectionDumper {
 public:
  void section(const char* name) { out_ << name << ":\n"; }
  template <typename T>
  void operator()(const char* key, const T& field, const char* doc) {
    if constexpr (is_named_choice_v<T>) {
      line(key, choice_name(field), doc);
    } else {
      // fmt prints the shortest text that reads back to the same value (0.05, not 0.0500...01).
      line(key, fmt::format("{}", field), doc);
    }
  }
  [[nodiscard]] std::string str() const { return out_.str(); }

 protected:
  void line(const char* key, const std::string& value, const char* doc) {
    out_ << "  " << key << ": " << value << "  # " << doc << "\n";
  }

 private:
  std::ostringstream out_;
};

/// The one loader of every configuration file: `yaml` read over `base` through the key list
/// `visit(options, loader)` walks, every other section and key refused (but
/// `other_sections`, which another loader reads), then `check(options)`, whose
/// std::invalid_argument becomes the ParseError of the first key it names.
template <typename Options, typename Visit, typename Check>
Options parse_options(const std::string& yaml, const std::string& source, const Options& base, Visit&& visit,
                      Check&& check, const std::set<std::string>& other_sections = {}) {
  const YAML::Node root = parse_sections(yaml, source);
  Options o = base;
  if (root.IsNull()) return o;
  SectionLoader loader(root, source);
  visit(o, loader);
  loader.reject_unknown(other_sections);
  try {
    check(o);
  } catch (const std::invalid_argument& e) {
    loader.fail_impossible(e.what());
  }
  return o;
}

/// Every key `visit` walks, with its value in `options` and its documentation, as YAML.
template <typename Options, typename Visit>
std::string dump_options(const Options& options, Visit&& visit) {
  Options copy = options;  // the key list takes fields by reference, for the loader
  SectionDumper d;
  visit(copy, d);
  return d.str();
}

}  // namespace lookahead::slam::config
