#pragma once
// The known name nearest to a mistyped one, for the "did you mean 'algorithm'?" of input
// errors (unknown scenario keys, planner names, enumerated values). Case is ignored, and the
// distance is Damerau-Levenshtein's (insertions, deletions, substitutions and swaps of two
// neighbouring letters each count 1): "algoritm", "algorihtm" and "Algorithm" all find
// "algorithm"; a name cut short finds the one it begins.
#include <string>
#include <vector>

namespace wpg {

// `text` in lower case (ASCII letters only; other bytes unchanged).
std::string asciiLower(std::string text);

// The edit distance above between `a` and `b`, case ignored.
std::size_t nameDistance(const std::string& a, const std::string& b);

// The entry of `known` nearest to `given`, or "" when none is near enough to be a typo of it:
// a distance of at most max(1, length / 3) of the longer name (two edits in "algorithm"), and
// a unique nearest entry (a tie suggests nothing); failing that, the one entry that `given`
// (3 letters or more) begins ("max_step_yaw" for "max_step_yaw_change").
std::string nearestName(const std::string& given, const std::vector<std::string>& known);

// "; did you mean 'NAME'?" for the nearest name, "" when there is none.
std::string didYouMean(const std::string& given, const std::vector<std::string>& known);

}  // namespace wpg
