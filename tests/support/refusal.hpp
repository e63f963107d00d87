#pragma once
// The refusal a call makes: the tests of every folder check that bad input
// is refused with the right id, place and message.
#include <gtest/gtest.h>

#include "bezcam/error.hpp"

namespace bezcam::test {

/// Runs `f` and returns the InputError it throws; fails the test (and
/// returns an empty error) when it throws none.
template <class F>
InputError refusal_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a refusal";
  return InputError(ErrorId(""), Place{}, "");
}

}  // namespace bezcam::test
