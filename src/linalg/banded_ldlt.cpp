#include "linalg/banded_ldlt.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace fabform {

BandedLdlt::BandedLdlt(int size, int bandwidth) : size_(size), bandwidth_(bandwidth) {
  if (size < 0 || bandwidth < 0) throw std::invalid_argument("BandedLdlt: a negative size or bandwidth");
  bandwidth_ = std::min(bandwidth, std::max(size - 1, 0));
  lower_.assign(static_cast<std::size_t>(size_) * static_cast<std::size_t>(bandwidth_), 0.0);
  diagonal_.assign(static_cast<std::size_t>(size_), 0.0);
}

double& BandedLdlt::at(int row, int column) {
  if (column < 0 || row >= size_ || column > row || row - column > bandwidth_)
    throw std::out_of_range("BandedLdlt::at: outside the lower band");
  if (row == column) return diagonal_[static_cast<std::size_t>(row)];
  return lower_[static_cast<std::size_t>(row) * static_cast<std::size_t>(bandwidth_) +
                static_cast<std::size_t>(column - row + bandwidth_)];
}

std::size_t BandedLdlt::first_place(int r) const {
  return static_cast<std::size_t>(std::max(0, bandwidth_ - r));
}

// Row by row: L(r, c) = (A(r, c) − Σₖ L(r, k) D(k) L(c, k)) / D(c) for c < r, then
// D(r) = A(r, r) − Σₖ L(r, k)² D(k), k over the columns both rows' bands hold. Row r's place p
// holds column r − w + p, so column k sits at place k − r + w in row r and k − c + w in row c.
bool BandedLdlt::factorise() {
  const std::size_t w = static_cast<std::size_t>(bandwidth_);
  std::vector<double> scaled(w);  // L(r, k) D(k), by row r's places
  for (int r = 0; r < size_; ++r) {
    const std::size_t row = static_cast<std::size_t>(r) * w;
    const std::size_t first = first_place(r);
    for (std::size_t p = first; p < w; ++p) {
      const std::size_t c = static_cast<std::size_t>(r) - w + p;
      double sum = lower_[row + p];
      for (std::size_t k = first; k < p; ++k) sum -= scaled[k] * lower_[c * w + k + w - p];
      lower_[row + p] = sum / diagonal_[c];
      scaled[p] = sum;
    }
    double d = diagonal_[static_cast<std::size_t>(r)];
    for (std::size_t p = first; p < w; ++p) d -= scaled[p] * lower_[row + p];
    if (d == 0.0) return false;
    diagonal_[static_cast<std::size_t>(r)] = d;
  }
  return true;
}

void BandedLdlt::solve_in_place(Eigen::Ref<Eigen::VectorXd> b) const {
  if (b.size() != size_) throw std::invalid_argument("BandedLdlt::solve_in_place: b has the wrong size");
  const std::size_t w = static_cast<std::size_t>(bandwidth_);
  for (int r = 0; r < size_; ++r) {
    const std::size_t row = static_cast<std::size_t>(r) * w;
    const Eigen::Index first_column = r - bandwidth_;
    double sum = b[r];
    for (std::size_t p = first_place(r); p < w; ++p)
      sum -= lower_[row + p] * b[first_column + static_cast<Eigen::Index>(p)];
    b[r] = sum;
  }
  for (int r = 0; r < size_; ++r) b[r] /= diagonal_[static_cast<std::size_t>(r)];
  for (int r = size_ - 1; r >= 0; --r) {
    const std::size_t row = static_cast<std::size_t>(r) * w;
    const Eigen::Index first_column = r - bandwidth_;
    const double x = b[r];
    for (std::size_t p = first_place(r); p < w; ++p)
      b[first_column + static_cast<Eigen::Index>(p)] -= lower_[row + p] * x;
  }
}

}  // namespace fabform
