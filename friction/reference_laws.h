#pragma once
// The laws that need GSL (GPL-3): `exact-reference`, the brute-force cross-check of `exact`
// (friction/exact_reference_law.h). They live in their own library, frictionlab::friction_reference,
// so that frictionlab::friction (every other law) links no GPL code; a program that wants them
// links that library and calls register_reference_laws() once, before it asks for them by name
// (the command, the Python module, the benchmarks and the tests that use them do).

namespace frictionlab::friction {

/// Registers `exact-reference` as a built-in law (friction/registry.h). Thread-safe; calls after
/// the first do nothing.
void register_reference_laws();

}  // namespace frictionlab::friction
