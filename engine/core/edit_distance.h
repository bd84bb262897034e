#pragma once
// "Did you mean" for names a user typed (scene keys, commands, options): the closest candidate
// by optimal string alignment distance.
#include <cstddef>
#include <string_view>
#include <vector>

namespace pyro {

// Optimal string alignment distance (Levenshtein plus adjacent transpositions, so that
// "raduis" is one edit from "radius").
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `wrong` when it is within `max_distance` edits (the first of equal
// ones); empty otherwise, and for a `wrong` longer than 64 bytes (no name is near that long: the
// cost stays bounded whatever the input).
std::string_view closest_candidate(std::string_view wrong, const std::vector<std::string_view>& candidates,
                                   std::size_t max_distance = 2);

}  // namespace pyro
