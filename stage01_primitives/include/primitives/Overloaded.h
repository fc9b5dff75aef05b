#pragma once
/// @file Overloaded.h
/// A visitor made of lambdas, one per alternative of a std::variant:
///
///     std::visit(Overloaded{[](const Sphere& s) { ... }, [](const Plane& p) { ... }}, shape);
///
/// The closed sets of the engine (shapes, lights) are variants, and every operation on them is a
/// visit; this is the one helper they share.

namespace rt {

template <typename... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <typename... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace rt
