#pragma once
/// @file NearestName.h
/// The "did you mean" of every message about a misspelt name: `rt`'s commands, options, scenes
/// and tracers, and a scene file's keys, types and material names. One rule for all of them.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace rt {

/// The known name nearest to word, when near enough to be a plausible typo; empty otherwise.
///
/// Nearness is the optimal string alignment distance (Levenshtein's insertions, deletions and
/// substitutions, plus the swap of two adjacent characters, each one edit), ignoring case: a
/// swap is the most common typo ("raduis"), and "kd" for "kD" is a slip, not a new word. A name
/// k is near when the distance is at most max(1, min(3, |k| / 3)): one edit in a name of up to
/// five characters, a third of a longer one, never more than three, so that short words do not
/// suggest unrelated short names. Among several near names the nearest wins, the first listed
/// on a tie.
///
/// When no name is near by that rule, a name that contains the word or is contained in it
/// (ignoring case; a prefix is one case) is suggested, provided the shorter of the two has at
/// least three characters: "spotlight" suggests "spot", "cyl" suggests "cylinder", while "st"
/// suggests nothing. Among several such names the one whose length differs least from the
/// word's wins, the first listed on a tie.
std::string_view nearestName(std::string_view word, std::span<const std::string_view> known);

/// "; did you mean 'NAME'?" for the nearest name, or "" when no name is near.
std::string didYouMean(std::string_view word, std::span<const std::string_view> known);

/// The names with separator between them ("a, b, c"); after the first `most` names,
/// " and N more".
std::string joinNames(std::span<const std::string_view> names, std::string_view separator = ", ",
                      std::size_t most = SIZE_MAX);

/// The message for a name that is not one of known: "unknown WHAT 'WORD'; did you mean 'NAME'?
/// (known: a b c)", without the suggestion when no name is near ("unknown tracer 'phog'; did you
/// mean 'phong'? (known: rays normals ...)").
std::string unknownNameMessage(std::string_view what, std::string_view word,
                               std::span<const std::string_view> known);

/// The message for a name that a stage this build does not include would know: "the WHAT 'NAME'
/// needs STAGE, which this build does not include (a course cut before it)".
std::string needsStageMessage(std::string_view what, std::string_view name, std::string_view stage);

}  // namespace rt
