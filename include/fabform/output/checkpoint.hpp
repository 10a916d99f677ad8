#pragma once
// checkpoint.bin in a results folder: a run's solver state in full double precision (positions,
// contacts and what the solver carries between iterations) and its summary so far, so that
// `fabform run --resume DIR` goes on exactly where the run stopped. Binary, in the machine's
// byte order (a marker refuses another), ending in a checksum that refuses a damaged file.
#include <string>

#include "fabform/solver/solver_state.hpp"
#include "fabform/solver/summary.hpp"

namespace fabform {

struct Checkpoint {
  SolverState state;
  Summary summary;  // the solver, iterations, seconds and history so far
};

/// The file's bytes for this state and summary.
std::string checkpoint_bytes(const SolverState& state, const Summary& summary);

/// Reads a checkpoint written for a model of `node_count` nodes and `body_count` bodies; throws
/// InputError naming the file and what is wrong (missing, damaged, or made for another model).
Checkpoint read_checkpoint(const std::string& path, int node_count, int body_count);

}  // namespace fabform
