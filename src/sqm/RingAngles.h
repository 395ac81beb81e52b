/// \file
/// RingAngles: the angles of a ring of vertices around an axis, made to turn monotonically.
///
/// Projected along a tube's path (or onto the plane that closes a cycle), a BNP one-ring is not always
/// star-shaped about the axis: after LIE splits and smoothing it can bend back on itself. A copy of it
/// would fold, and the tube's quads cut through each other (the octopus's tentacles: 134 intersecting
/// triangle pairs before, 24 after); a zip along such angles pinches the band (the pretzel). The angles
/// are blended towards equal spacing just enough that every step turns forward by at least a fifth of an
/// equal step; a ring whose winding number is not +-1 gets equal spacing. The first angle stays.
#pragma once

#include <vector>

namespace medial {

/// angle[k]: the angle of the ring's k-th vertex (radians, any branch). wantedSense: +1 or -1 when the
/// ring must turn that way (a ring turning the other way gets equal spacing), 0 to keep the way it turns.
/// Returns whether the angles changed.
bool untangleAngles(std::vector<double>& angle, int wantedSense = 0);

}  // namespace medial
