#pragma once
// The figures engineers read off a formed fabric: its area flat and formed, the area resting
// on the bodies, the largest and smallest warp and weft strains and where they are (the
// smallest, negative, says where the fabric is compressed: where it gathers), and how the fabric's
// area spreads over strain (area-weighted histograms, warp and weft).
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

/// The most stretched (or most compressed) spring of one direction: its strain, its first node's
/// lattice indices and its midpoint in the formed fabric.
struct StrainPeak {
  double strain = 0.0;
  int i = -1, j = -1;
  Eigen::Vector3d at_m = Eigen::Vector3d::Zero();
};

/// Bins [edges[b], edges[b+1]) of strain and the formed area of the faces whose mean warp
/// (weft) strain falls in each; every face with warp (weft) sides counts once in that histogram.
struct StrainHistogram {
  std::vector<double> edges;
  std::vector<double> warp_area_m2;
  std::vector<double> weft_area_m2;
};

struct FabricFigures {
  double area_flat_m2 = 0.0;    // the fabric before forming (W × H for a rectangle)
  double area_formed_m2 = 0.0;  // the formed faces, a four-sided one as two triangles
  double contact_area_m2 = 0.0;  // the share of formed area around the nodes on a body
  StrainPeak max_warp;
  StrainPeak max_weft;
  StrainPeak min_warp;
  StrainPeak min_weft;
  StrainHistogram histogram;
};

/// A face of the fabric as formed: its area and the mean strain of its warp sides and of its
/// weft sides (NaN where it has none of a kind, as some of an arc mesh's faces).
struct FormedCell {
  double area_m2;
  double warp_strain;
  double weft_strain;
};

/// The warp or weft spring joining nodes p and q (an index into springs()), or -1.
int stretch_spring_between(const Fabric& fabric, int p, int q);

/// Every face of the fabric at `x`, in the order of fabric.faces().
std::vector<FormedCell> formed_cells(const Model& model, const std::vector<Eigen::Vector3d>& x);

/// The figures of the fabric at `x`; `contact` flags the nodes resting on a body (one per node).
FabricFigures fabric_figures(const Model& model, const std::vector<Eigen::Vector3d>& x,
                             const std::vector<unsigned char>& contact);

}  // namespace fabform
