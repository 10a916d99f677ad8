#pragma once
// Finding a model's term of a given type, for tests that inspect what the builder made.
#include "fabform/model/model.hpp"

namespace fabform::test {

/// The model's first term of type T, or nullptr when it has none.
template <class T>
const T* find_term(const Model& model) {
  for (const auto& term : model.terms)
    if (const auto* found = dynamic_cast<const T*>(term.get())) return found;
  return nullptr;
}

}  // namespace fabform::test
