#pragma once
// Friction laws by spec, with what callers need to know about each. Callers choose a law once,
// from a spec (friction/law_spec.h: a name, or a name with parameters such as
// `exact:pressure=uniform`), and never branch on it again: a per-law fact (which law is the
// reference, which is too slow for simulations, which has poles, which symmetries it keeps) is
// read from here.
//
// The built-in laws are registered here; user code adds its own with register_law() (before it
// asks for them by name, from any thread), with no edit to this file: docs/extending.md.
//
// An alias is another name for a law, or for one of its specs: `moller-ellipsoidal` stands for
// `ellipsoidal`, `coulomb-decoupled` for `decoupled` (the names older scenarios, runs and docs
// use). It works wherever a name does (make_law(), scenario files, studies, the command line),
// the law it makes keeps the spec as written (spec(): "moller-ellipsoidal") and its own name()
// ("ellipsoidal"), and listings show each law once, with its aliases.

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "friction/law.h"
#include "friction/law_spec.h"

namespace frictionlab::friction {

/// Another name for a law spec (register_law_alias()).
struct LawAlias {
  std::string name;  ///< the alias, a NAME of the spec grammar, e.g. "moller-ellipsoidal"
  std::string spec;  ///< what it stands for: a law's name, or a spec of that law with parameters
};

/// A registered law (with given arguments) and its facts.
struct LawInfo {
  std::string name;                      ///< registry name, e.g. "exact"
  std::string spec;                      ///< the spec described, verbatim (list_laws(): the name)
  std::string summary;                   ///< one line: what the law is, where it comes from, its accuracy
  std::vector<LawParameter> parameters;  ///< what a spec may set (friction/law_spec.h)
  std::vector<LawAlias> aliases;         ///< the law's other names (of it, or of specs of it), in
                                         ///< the order registered
  bool reference = false;  ///< the law every other law is measured against (exactly one, at its
                           ///< defaults: `exact` and `exact:pressure=hertz`, not `exact:pressure=uniform`)
  bool slow = false;       ///< milliseconds per call: a cross-check for tests and small studies,
                           ///< not for simulations or full accuracy grids
  bool has_poles = false;  ///< FrictionLaw::has_poles(): it declares denominators to watch
  LawPromises promises;    ///< FrictionLaw::promises()
};

/// Every registered law with its parameters at their defaults, each once (an alias is not an entry
/// of its own: it is in its law's LawInfo::aliases), in a stable order (the reference first, then
/// the built-in laws, then user-registered ones in the order registered).
[[nodiscard]] std::vector<LawInfo> list_laws();

/// Every registered law by name, each followed by its variants: the specs that set one choice
/// parameter to a non-default value (e.g. "exact:pressure=uniform"). What the soundness tests and
/// the benchmark run over. No aliases.
[[nodiscard]] std::vector<std::string> list_law_specs();

/// The facts of the law `spec` denotes (spec may use an alias: name is then the law's, spec the
/// one given); std::invalid_argument as make_law().
[[nodiscard]] LawInfo law_info(std::string_view spec);

/// The law `spec` denotes, its spec() the spec verbatim. NAME may be an alias: ALIAS:KEY=VALUE is
/// the alias's spec with KEY=VALUE added (a key the alias already sets is an error).
/// std::invalid_argument naming the spec on an unknown law (listing the known names and aliases),
/// an unknown or repeated key (listing the law's keys) or a bad value (naming the rule).
[[nodiscard]] std::unique_ptr<FrictionLaw> make_law(std::string_view spec);

/// The canonical form of `spec` (LawArguments::canonical()): two specs denote the same law iff
/// their canonical forms are equal; an alias's is its target's ("moller-ellipsoidal" ->
/// "ellipsoidal"). Validates like make_law().
[[nodiscard]] std::string canonical_law_spec(std::string_view spec);

/// The name of the reference law ("exact"): the one every other law is compared with.
[[nodiscard]] std::string reference_law_name();

/// A new instance of the reference law.
[[nodiscard]] std::unique_ptr<FrictionLaw> make_reference_law();

// ---------------------------------------------------------------------------------------------
// Registration from user code.

/// Makes a law from its validated arguments. It must return a law whose name() is the registered
/// name; it may throw std::invalid_argument for a combination of values it rejects.
using LawFactory = std::function<std::unique_ptr<FrictionLaw>(const LawArguments&)>;

/// How a law is used, beyond what it computes (which the law itself says: has_poles(), promises()).
struct LawFacts {
  bool slow = false;  ///< milliseconds per call: kept out of simulations and full study grids
};

/// Everything the registry needs to know of a law.
struct LawRegistration {
  std::string name;                      ///< NAME of the grammar (friction/law_spec.h), not yet taken
  std::string summary;                   ///< one line for `frictionlab laws`
  std::vector<LawParameter> parameters;  ///< may be empty
  LawFacts facts;
  LawFactory factory;
};

/// Adds a law, known from then on to make_law(), list_laws(), the command line, scenario files,
/// studies and benchmarks. Thread-safe. std::invalid_argument if the name is taken (by a law or
/// an alias, built-in or registered), the name or a parameter declaration breaks the grammar, the
/// summary is empty or there is no factory.
void register_law(LawRegistration registration);

/// The short form for a law without parameters: register_law({name, summary, {}, {}, factory})
/// with a factory that ignores its (empty) arguments.
void register_law(std::string name, std::string summary, std::function<std::unique_ptr<FrictionLaw>()> factory);

/// Registers a law when constructed: a namespace-scope `static const LawRegistrar` in the user's
/// own source file adds the law before main() runs (std::invalid_argument then terminates the
/// program, as any exception thrown during static initialisation does). The object file must be
/// linked into the program (a static library member nothing refers to is dropped by the linker).
struct LawRegistrar {
  explicit LawRegistrar(LawRegistration registration) { register_law(std::move(registration)); }
};

/// Removes a law added by register_law(), and every alias of it (laws already made stay valid).
/// Returns false if no such law was registered; std::invalid_argument for a built-in law.
/// Thread-safe.
bool unregister_law(std::string_view name);

/// Adds `alias` as another name for `spec` (a registered law's name, or a spec of it such as
/// "exact:pressure=uniform"), known from then on wherever a name is. Thread-safe.
/// std::invalid_argument naming the alias if it breaks the grammar of NAME or is taken (by a law
/// or an alias), and naming the spec if it is not a valid spec of a registered law (an alias as
/// the target is refused too: name the law it stands for).
void register_law_alias(std::string alias, std::string spec);

/// Removes an alias added by register_law_alias(). Returns false if there is no such alias;
/// std::invalid_argument for a built-in alias. Thread-safe.
bool unregister_law_alias(std::string_view alias);

}  // namespace frictionlab::friction
