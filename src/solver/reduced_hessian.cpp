#include "solver/reduced_hessian.hpp"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>

#include "fabform/thread_count.hpp"
#include "linalg/parallel_failure.hpp"

namespace fabform {
namespace {

std::size_t at(int index) { return static_cast<std::size_t>(index); }

// Sums each block the terms hand, in the free directions, into its pair, the lower one (a pair's
// transpose is the other), in the order handed (so the sums are those of a list of entries
// summed in that order); notes the pairs there is no block for. Keeps the pairs whose column
// node is in [first_column, end_column) and passes over the others.
class PairSums final : public StiffnessSink {
 public:
  PairSums(const FreeDirections& directions, const std::vector<int>& start, const std::vector<int>& row,
           std::vector<Eigen::Matrix3d>* block, double slack_share, int first_column, int end_column)
      : d_(directions),
        start_(start),
        row_(row),
        block_(block),
        slack_share_(slack_share),
        first_column_(first_column),
        end_column_(end_column) {}

  void add(int row, int col, const Eigen::Matrix3d& stiffness) override {
    if (row >= col) {
      if (keeps(col)) sum(row, col, stiffness);
    } else if (keeps(row)) {
      sum(col, row, stiffness.transpose());
    }
  }
  double slack_share() const override { return slack_share_; }
  // From 8192 items, the column nodes shared in ranges among the threads, each thread's sink
  // keeping its range's pairs.
  void add_each(std::size_t count, const std::function<void(std::size_t, StiffnessSink&)>& each) override {
    const int parts = count >= static_cast<std::size_t>(kMinParallelItems) ? threads_in_use() : 1;
    if (parts == 1) return StiffnessSink::add_each(count, each);
    std::vector<PairSums> shares;
    const auto columns = static_cast<long long>(end_column_ - first_column_);
    for (int t = 0; t < parts; ++t)
      shares.emplace_back(d_, start_, row_, block_, slack_share_,
                          first_column_ + static_cast<int>(columns * t / parts),
                          first_column_ + static_cast<int>(columns * (t + 1) / parts));
    ParallelFailure failure;
#pragma omp parallel for schedule(static, 1) num_threads(parts)
    for (int t = 0; t < parts; ++t) {
      try {
        for (std::size_t k = 0; k < count && !failure.caught(); ++k) each(k, shares[static_cast<std::size_t>(t)]);
      } catch (...) {
        failure.capture();
      }
    }
    failure.rethrow();
    for (PairSums& share : shares) missing_.insert(missing_.end(), share.missing_.begin(), share.missing_.end());
  }
  std::vector<std::pair<int, int>>& missing() { return missing_; }

 private:
  bool keeps(int column) const { return column >= first_column_ && column < end_column_; }
  void sum(int i, int j, const Eigen::Matrix3d& stiffness) {
    const auto first = row_.begin() + start_[at(j)], last = row_.begin() + start_[at(j) + 1];
    const auto found = std::lower_bound(first, last, i);
    if (found == last || *found != i) missing_.emplace_back(i, j);
    else (*block_)[static_cast<std::size_t>(found - row_.begin())] += d_.of(i).transpose() * stiffness * d_.of(j);
  }

  const FreeDirections& d_;
  const std::vector<int>& start_;
  const std::vector<int>& row_;
  std::vector<Eigen::Matrix3d>* block_;
  double slack_share_;
  int first_column_, end_column_;
  std::vector<std::pair<int, int>> missing_;
};

}  // namespace

bool ReducedHessian::sum_blocks(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                const FreeDirections& directions, const Term* lagged, double slack_share) {
  std::fill(block_.begin(), block_.end(), Eigen::Matrix3d::Zero());
  PairSums sums(directions, start_, row_, &block_, slack_share, 0, model.node_count());
  for (const auto& term : model.terms) term->add_stiffness(model, x, sums);
  if (lagged) lagged->add_stiffness(model, x, sums);
  if (sums.missing().empty()) return true;
  add_pairs(model.node_count(), std::move(sums.missing()));
  return false;
}

// The pairs kept and `missing`, and every node's own (the diagonal is always stored).
void ReducedHessian::add_pairs(int nodes, std::vector<std::pair<int, int>> missing) {
  std::vector<std::pair<int, int>> pairs = std::move(missing);  // (column, row)
  for (auto& [i, j] : pairs) std::swap(i, j);
  for (int j = 0; j < nodes; ++j) {
    pairs.emplace_back(j, j);
    if (at(j) + 1 < start_.size())
      for (int p = start_[at(j)]; p < start_[at(j) + 1]; ++p) pairs.emplace_back(j, row_[at(p)]);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  start_.assign(at(nodes) + 1, 0);
  row_.clear();
  for (const auto& [j, i] : pairs) {
    ++start_[at(j) + 1];
    row_.push_back(i);
  }
  for (std::size_t j = 0; j < at(nodes); ++j) start_[j + 1] += start_[j];
  block_.assign(row_.size(), Eigen::Matrix3d::Zero());
}

// The entries of node j's columns: for each pair (i, j), node i's slots (the diagonal pair's
// lower triangle only).
int ReducedHessian::column_entries(const FreeDirections& d, int j) const {
  int entries = 0;
  for (int p = start_[at(j)]; p < start_[at(j) + 1]; ++p) {
    const int i = row_[at(p)];
    entries += i == j ? d.count(j) * (d.count(j) + 1) / 2 : d.count(i) * d.count(j);
  }
  return entries;
}

// Column by column of unknowns: a column of node j holds, for each pair (i, j) in ascending i,
// the rows of node i's slots (from the column's own on the diagonal). Each node's columns are
// written where the nodes before it end, so they are written on every thread.
Eigen::SparseMatrix<double> ReducedHessian::written_out(const FreeDirections& d) const {
  const int nodes = static_cast<int>(start_.size()) - 1;
  std::vector<int> first(at(nodes) + 1, 0);  // per node: its columns' first entry
#pragma omp parallel for schedule(static) if (nodes >= kMinParallelItems)
  for (int j = 0; j < nodes; ++j) first[at(j) + 1] = column_entries(d, j);
  for (int j = 0; j < nodes; ++j) first[at(j) + 1] += first[at(j)];
  Eigen::SparseMatrix<double> m(d.unknowns(), d.unknowns());
  m.resizeNonZeros(first.back());
  int* outer = m.outerIndexPtr();
  int* inner = m.innerIndexPtr();
  double* value = m.valuePtr();
#pragma omp parallel for schedule(static) if (nodes >= kMinParallelItems)
  for (int j = 0; j < nodes; ++j) {
    int written = first[at(j)];
    for (int q = 0; q < d.count(j); ++q) {
      outer[d.offset[at(j)] + q] = written;
      for (int p = start_[at(j)]; p < start_[at(j) + 1]; ++p) {
        const int i = row_[at(p)];
        for (int r = i == j ? q : 0; r < d.count(i); ++r) {
          inner[written] = d.offset[at(i)] + r;
          value[written++] = block_[at(p)](r, q);
        }
      }
    }
  }
  outer[d.unknowns()] = first.back();
  return m;
}

Eigen::SparseMatrix<double> ReducedHessian::assemble(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                                     const FreeDirections& directions, const Term* lagged,
                                                     double slack_share) {
  if (start_.size() != at(model.node_count()) + 1) {  // a model of another size: start again
    start_.assign(1, 0);
    row_.clear();
    add_pairs(model.node_count(), {});
  }
  // Again with the pairs a pass found, until none is missing (the pairs only grow, so it ends;
  // the terms hand the same pairs each time, so at most twice).
  while (!sum_blocks(model, x, directions, lagged, slack_share)) {
  }
  return written_out(directions);
}

Eigen::SparseMatrix<double> reduced_hessian(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                            const FreeDirections& directions, const Term* lagged) {
  return ReducedHessian().assemble(model, x, directions, lagged);
}

}  // namespace fabform
