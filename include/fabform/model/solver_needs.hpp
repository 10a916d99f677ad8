#pragma once
// What a term, or a scene's feature, asks of the solver that carries it. Each solver declares what
// it gives (SolverEntry::gives, solver_registry.hpp), in one table: the scene reader asks it
// (solver_gives), naming the scene's key, and each solver asks it of its model on entry
// (solver_refusal).
#include <string>

namespace fabform {

enum class SolverNeed : unsigned {
  velocity = 1u << 0,        // a force that depends on the nodes' velocities (wind's drag)
  stick = 1u << 1,           // friction's stick, and the slip from where a node landed
  stiff_penalty = 1u << 2,   // a stiffness far above the fabric's, taken into the step's matrix
  no_time_step = 1u << 3,    // a stiffness no stable time step bounds (a spring wrapped over an edge)
  loading_branch = 1u << 4,  // hysteresis on its loading branch alone, along which nothing swings back
};

/// Every need, in the order they are declared (and said).
constexpr SolverNeed kEveryNeed[] = {SolverNeed::velocity, SolverNeed::stick, SolverNeed::stiff_penalty,
                                     SolverNeed::no_time_step, SolverNeed::loading_branch};

/// A set of needs.
class SolverNeeds {
 public:
  constexpr SolverNeeds() = default;
  constexpr SolverNeeds(SolverNeed need) : bits_(static_cast<unsigned>(need)) {}  // implicit: a set of one

  constexpr SolverNeeds operator|(SolverNeeds other) const { return SolverNeeds(bits_ | other.bits_); }
  constexpr SolverNeeds operator-(SolverNeeds other) const { return SolverNeeds(bits_ & ~other.bits_); }
  constexpr bool contains(SolverNeeds other) const { return (bits_ & other.bits_) == other.bits_; }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr bool operator==(SolverNeeds other) const { return bits_ == other.bits_; }

  /// Each need in it, said as to_string says it, joined by " and "; "" when empty.
  std::string said() const;

 private:
  constexpr explicit SolverNeeds(unsigned bits) : bits_(bits) {}
  unsigned bits_ = 0;
};

constexpr SolverNeeds operator|(SolverNeed a, SolverNeed b) { return SolverNeeds(a) | SolverNeeds(b); }

/// What a need asks, said in a message: "a force that depends on the fabric's velocity".
std::string to_string(SolverNeed need);

}  // namespace fabform
