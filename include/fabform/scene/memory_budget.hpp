#pragma once
// A run too large for the machine is refused before anything is allocated, with the estimate and
// what the machine has, rather than ending in std::bad_alloc or the kernel's OOM killer.
#include <string>

#include "fabform/fabric/fabric_layout.hpp"
#include "fabform/scene/scene.hpp"

namespace fabform {

/// The nodes `spec` makes, counted without laying them out (a circle's lattice approximately).
double expected_nodes(const FabricSpec& spec);

/// A lower bound of the bytes a run of `nodes` nodes takes with `solver`: what it needs at least,
/// so that a run refused certainly would not fit.
double least_run_bytes(double nodes, const std::string& solver);

/// The memory this process can still take, in bytes: the kernel's MemAvailable, within a cgroup's
/// limit if there is one; infinity where neither can be read.
double available_memory_bytes();

/// Throws InputError at the fabric's divisions when the scene's run cannot fit in `available`
/// bytes, naming the estimate and what is available.
void check_memory_budget(const Scene& scene, double available = available_memory_bytes());

}  // namespace fabform
