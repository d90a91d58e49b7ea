// SPDX-License-Identifier: MIT
// Named choices: an enum whose values have names in the YAML files. The enum's own header
// declares its name table beside it, found by argument-dependent lookup:
//
//   enum class ProposalKind { kScanMatch, kMotionModel };
//   constexpr std::array<std::pair<ProposalKind, const char*>, 2> choice_names(ProposalKind) {
//     return {{{ProposalKind::kScanMatch, "scan_match"}, {ProposalKind::kMotionModel,
//     "motion_model"}}};
//   }
//
// and the shared section loader and dumper (yaml_sections.hpp) read and print it by name.
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <utility>

namespace lookahead::slam::config {

/// Does `E` have a name table (a `choice_names(E)` found by argument-dependent lookup)?
template <typename E, typename = void>
struct is_named_choice : std::false_type {};
template <typename E>
struct is_named_choice<E, std::void_t<decltype(choice_names(std::declval<E>()))>> : std::is_enum<E> {};
template <typename E>
inline constexpr bool is_named_choice_v = is_named_choice<E>::value;

/// The name of `value` ("" for a value the table does not list).
template <typename E>
const char* choice_name(E value) {
  for (const auto& [v, name] : choice_names(value)) {
    if (v == value) return name;
  }
  return "";
}

/// The value named `name`, if the table lists it.
template <typename E>
std::optional<E> choice_from_name(const std::string& name) {
  for (const auto& [v, n] : choice_names(E{})) {
    if (name == n) return v;
  }
  return std::nullopt;
}

/// The allowed names, "a | b | c", for error messages and documentation.
template <typename E>
std::string choice_list() {
  std::string out;
  for (const auto& entry : choice_names(E{})) out += (out.empty() ? "" : " | ") + std::string(entry.second);
  return out;
}

}  // namespace lookahead::slam::config
