#pragma once
/// @file NearestName.h
/// The "did you mean" of every message about a misspelt name: `rt`'s commands, options, scenes
/// and tracers, and a scene file's keys, types and material names. One rule for all of them.

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

}  // namespace rt
