#include "common/NearestName.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace rt {

namespace {

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

/// Optimal string alignment distance between a and b, ignoring case; any distance above bound
/// is returned as bound + 1 (the search stops as soon as every cell of a row exceeds it).
std::size_t editDistance(std::string_view a, std::string_view b, std::size_t bound) {
  const std::size_t lengthGap = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
  if (lengthGap > bound) return bound + 1;
  // Three rows of the dynamic-programming table: i - 2, i - 1 and i.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    std::size_t rowMin = current[0];
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1]))
        current[j] = std::min(current[j], before[j - 2] + 1);
      rowMin = std::min(rowMin, current[j]);
    }
    if (rowMin > bound) return bound + 1;
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return std::min(previous[b.size()], bound + 1);
}

/// Whether the shorter of a and b, at least MIN_CONTAINED characters long, occurs in the longer
/// one, ignoring case.
bool containsEither(std::string_view a, std::string_view b) {
  constexpr std::size_t MIN_CONTAINED = 3;
  const std::string_view shorter = a.size() < b.size() ? a : b;
  const std::string_view longer = a.size() < b.size() ? b : a;
  if (shorter.size() < MIN_CONTAINED) return false;
  const auto same = [](char x, char y) { return lower(x) == lower(y); };
  return std::search(longer.begin(), longer.end(), shorter.begin(), shorter.end(), same) !=
         longer.end();
}

/// The known name that contains word or is contained in it, the closest in length, the first
/// listed on a tie; empty when there is none.
std::string_view containingName(std::string_view word, std::span<const std::string_view> known) {
  std::string_view best;
  std::size_t bestGap = 0;
  for (std::string_view k : known) {
    if (!containsEither(word, k)) continue;
    const std::size_t gap =
        k.size() > word.size() ? k.size() - word.size() : word.size() - k.size();
    if (best.empty() || gap < bestGap) {
      best = k;
      bestGap = gap;
    }
  }
  return best;
}

}  // namespace

std::string_view nearestName(std::string_view word, std::span<const std::string_view> known) {
  constexpr std::size_t MAX_EDITS = 3;
  std::string_view best;
  std::size_t bestDistance = MAX_EDITS + 1;
  for (std::string_view k : known) {
    const std::size_t allowed = std::clamp<std::size_t>(k.size() / 3, 1, MAX_EDITS);
    const std::size_t d = editDistance(word, k, allowed);
    if (d <= allowed && d < bestDistance) {
      best = k;
      bestDistance = d;
    }
  }
  return best.empty() ? containingName(word, known) : best;
}

std::string didYouMean(std::string_view word, std::span<const std::string_view> known) {
  const std::string_view near = nearestName(word, known);
  return near.empty() ? std::string() : "; did you mean '" + std::string(near) + "'?";
}

std::string joinNames(std::span<const std::string_view> names, std::string_view separator,
                      std::size_t most) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < most; ++i) {
    if (i) out += separator;
    out += names[i];
  }
  if (names.size() > most) out += " and " + std::to_string(names.size() - most) + " more";
  return out;
}

std::string unknownNameMessage(std::string_view what, std::string_view word,
                               std::span<const std::string_view> known) {
  return "unknown " + std::string(what) + " '" + std::string(word) + "'" + didYouMean(word, known) +
         " (known: " + joinNames(known, " ") + ")";
}

std::string needsStageMessage(std::string_view what, std::string_view name,
                              std::string_view stage) {
  return "the " + std::string(what) + " '" + std::string(name) + "' needs " + std::string(stage) +
         ", which this build does not include (a course cut before it)";
}

}  // namespace rt
