/// @file Reading and editing XML as text, where the file is changed before MuJoCo's compiler
/// reads it (urdf_text.hpp, newer_mjcf.hpp): only what those edits need, every other byte and line
/// break kept where it was.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eomgen {

/// Where the first element of this name opens at or after `from`, outside comments (npos: none).
std::size_t element_start(const std::string& text, const std::string& name, std::size_t from = 0);

/// The line, from 1, of the character at `at`.
int line_of(const std::string& text, std::size_t at);

/// Just past the '>' that closes the tag opening at `start` (npos: none).
std::size_t past_tag(const std::string& text, std::size_t start);

/// Where `name="value"` (either quote) stands in the tag [start, end): from the name to just past
/// the closing quote, the name standing alone (not the tail of another); nothing when it does not.
std::optional<std::pair<std::size_t, std::size_t>> attribute_span(const std::string& text, std::size_t start,
                                                                  std::size_t end, const std::string& name);

/// The value of attribute `name` in the tag [start, end), or nothing.
std::optional<std::string> attribute(const std::string& text, std::size_t start, std::size_t end, const std::string& name);

/// Whether a tag of one of `elements` (outside comments) sets `name`.
bool any_tag_sets(const std::string& text, const std::vector<std::string>& elements, const std::string& name);

/// `text` without attribute `name` in every `element` tag (outside comments); nothing else moves.
std::string with_attribute_removed(const std::string& text, const std::string& element, const std::string& name);

/// MJCF's actuator elements (their tags, and their defaults'), whose attributes MuJoCo keeps per actuator.
const std::vector<std::string>& mjcf_actuator_elements();

/// `text` with attribute `from` of every `element` tag (outside comments) renamed `to`, its value kept.
std::string with_attribute_renamed(const std::string& text, const std::string& element, const std::string& from, const std::string& to);

/// The three numbers of attribute `name` ("x y z") in the tag [start, end), zeros where missing.
std::array<double, 3> triple_attribute(const std::string& text, std::size_t start, std::size_t end, const std::string& name);

/// `text` with `attributes` (` name="value"`, each with a space in front) in the <compiler> of its
/// <mujoco>: added to the compiler there, or in a <compiler> put first in <mujoco>, or for a URDF
/// without one in a <mujoco><compiler/></mujoco> put first in <robot>. Unchanged when that compiler
/// sets one of `names` itself, or there is no place for them (an empty root element).
std::string with_compiler_attributes(const std::string& text, const std::string& attributes, const std::vector<std::string>& names);

}  // namespace eomgen
