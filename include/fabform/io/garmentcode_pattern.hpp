#pragma once
// GarmentCode's sewing patterns (`*_specification.json`, MIT, Korosteleva et al.): panels as
// edge loops of vertices with Bézier curves given relative to their edge ([along, across] of the
// edge and its left normal) or circular arcs ([radius, large_arc, right], SVG's flags: `right`
// turns counter-clockwise), placed in space as R · (x, y, 0) + translation with
// R = Rz · Ry · Rx of `rotation` in degrees, lengths in the pattern's unit (`units_in_meter` of
// them to the metre); stitches pair two panel edges, the second taken from its end unless the
// stitch says "right_wrong". Read here, at the edge; fabform sees PanelSpecs and seams.
#include <array>
#include <string>
#include <vector>

#include "fabform/fabric/panel_spec.hpp"

namespace fabform {

struct SewingPattern {
  struct Stitch {
    std::array<int, 2> panel = {0, 0};
    std::array<int, 2> edge = {0, 0};
    bool same_direction = false;
  };
  std::vector<PanelSpec> panels;  // metres; grain_deg as given to the reader
  std::vector<Stitch> stitches;
};

/// Reads a GarmentCode specification, each panel's warp at grain_deg in its plane. Throws
/// InputError naming the file and the JSON path of what is wrong.
SewingPattern read_garmentcode_pattern(const std::string& path, double grain_deg);

}  // namespace fabform
