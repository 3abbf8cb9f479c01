#include "friction/registry.h"
#include "friction/registry_extension.h"

#include <algorithm>
#include <mutex>
#include <shared_mutex>
#include <stdexcept>
#include <utility>

#include "friction/decoupled_law.h"
#include "friction/ellipsoidal_law.h"
#include "friction/exact_law.h"
#include "friction/exact_table_law.h"
#include "friction/fit_law.h"
#include "friction/mujoco_elliptic_law.h"
#include "friction/pade_printed_law.h"
#include "friction/pade_reconstructed_law.h"

namespace frictionlab::friction {
namespace {

// A law as the registry keeps it. Facts about how the law is used live here; what it computes
// (has_poles(), promises()) is the law's own.
struct Entry {
  std::string name;
  std::string summary;
  std::vector<LawParameter> parameters;
  LawFactory factory;
  bool reference = false;
  bool slow = false;
  bool built_in = false;
};

// An alias as the registry keeps it: its name, the spec it stands for (parsed; its name is a
// registered law's).
struct Alias {
  std::string name;
  ParsedLawSpec target;
  bool built_in = false;
};

// Makes the law `args` describes with `e`'s factory, checked to be the law registered.
std::unique_ptr<FrictionLaw> make_with(const Entry& e, const LawArguments& args) {
  std::unique_ptr<FrictionLaw> law = e.factory(args);
  if (!law) throw std::logic_error("the factory of friction law '" + e.name + "' made no law");
  if (law->name() != e.name) {
    throw std::logic_error("the factory of friction law '" + e.name + "' made a law named '" +
                           std::string(law->name()) + "'");
  }
  set_law_spec(*law, args.spec());
  return law;
}

template <class Law>
LawFactory plain() {
  return [](const LawArguments&) { return std::make_unique<Law>(); };
}

// A built-in law: its name and summary are the law's own.
Entry built_in(LawFactory factory, std::vector<LawParameter> parameters = {}, bool reference = false,
               bool slow = false) {
  const auto law = factory(LawArguments("", parameters));
  Entry e{std::string(law->name()), std::string(law->summary()), std::move(parameters), std::move(factory),
          reference, slow, /*built_in=*/true};
  check_law_declaration(e.name, e.parameters);
  return e;
}

class Registry {
 public:
  Registry() {
    // The built-in laws, the reference first.
    add(built_in([](const LawArguments& a) { return std::make_unique<ExactLaw>(parse_pressure(a.choice("pressure"))); },
                 ExactLaw::parameters(),
                 /*reference=*/true));
    // The exact law tabulated, for each pressure: its table is built at its first evaluation.
    add(built_in(
        [](const LawArguments& a) { return std::make_unique<ExactTableLaw>(parse_pressure(a.choice("pressure"))); },
        ExactTableLaw::parameters()));
    // The closed form fitted to the exact law, for each pressure (docs/fit.md).
    add(built_in([](const LawArguments& a) { return std::make_unique<FitLaw>(parse_pressure(a.choice("pressure"))); },
                 FitLaw::parameters()));
    // exact-reference, the GSL cross-check, is registered by its own library
    // (friction/reference_laws.h), so that the laws link no GPL code.
    add(built_in([](const LawArguments&) { return std::make_unique<PadePrintedLaw>(PadeAlpha::major); }));
    add(built_in([](const LawArguments&) { return std::make_unique<PadePrintedLaw>(PadeAlpha::minor); }));
    add(built_in(plain<PadeReconstructedLaw>()));
    // The engines' spin-friction laws (docs/engines.md), each with its length parameter.
    add(built_in([](const LawArguments& a) { return std::make_unique<EllipsoidalLaw>(a.number("Rb")); },
                 EllipsoidalLaw::parameters()));
    add(built_in([](const LawArguments& a) { return std::make_unique<MujocoEllipticLaw>(*a.number("torsional")); },
                 MujocoEllipticLaw::parameters()));
    add(built_in([](const LawArguments& a) { return std::make_unique<DecoupledLaw>(a.number("r_spin")); },
                 DecoupledLaw::parameters()));
    // Their Hertz-calibrated defaults under the names older scenarios, runs and docs use.
    add_alias(make_alias("moller-ellipsoidal", "ellipsoidal", /*built_in=*/true));
    add_alias(make_alias("coulomb-decoupled", "decoupled", /*built_in=*/true));
  }

  // The alias `name` of `spec`, checked (not yet added): std::invalid_argument naming the alias if
  // its name breaks the grammar, or if `spec` is not a spec of a registered law that its factory
  // accepts.
  Alias make_alias(std::string name, std::string_view spec, bool built_in) const {
    try {
      check_law_declaration(name, {});
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("friction law alias '" + name + "' is not a valid name: " + e.what());
    }
    try {
      ParsedLawSpec target = parse_law_spec(spec);
      const auto [entry, via] = find(target.name);
      if (via) {
        throw std::invalid_argument("'" + target.name + "' is an alias: give the spec it stands for, " +
                                    via->target.text);
      }
      (void)make_with(*entry, bind_law_spec(target, entry->parameters));  // the factory accepts it
      return {std::move(name), std::move(target), built_in};
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("friction law alias '" + name + "' cannot stand for '" + std::string(spec) +
                                  "': " + e.what());
    }
  }

  // std::invalid_argument if the name is taken (by a law or an alias).
  void add(Entry e) {
    const std::unique_lock lock(mutex_);
    check_free_locked(e.name);
    entries_.push_back(std::make_shared<const Entry>(std::move(e)));
  }

  // std::invalid_argument if the name is taken or the target law is gone.
  void add_alias(Alias a) {
    const std::unique_lock lock(mutex_);
    check_free_locked(a.name);
    if (!find_locked(a.target.name)) {
      throw std::invalid_argument("friction law alias '" + a.name + "': its law '" + a.target.name +
                                  "' was unregistered meanwhile");
    }
    aliases_.push_back(std::make_shared<const Alias>(std::move(a)));
  }

  // Removes a user law and its aliases.
  bool remove(std::string_view name) {
    const std::unique_lock lock(mutex_);
    const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e->name == name; });
    if (it == entries_.end()) return false;
    if ((*it)->built_in) {
      throw std::invalid_argument("friction law '" + std::string(name) + "' is built-in: only laws added by "
                                  "register_law() can be unregistered");
    }
    entries_.erase(it);
    std::erase_if(aliases_, [&](const auto& a) { return a->target.name == name; });
    return true;
  }

  bool remove_alias(std::string_view name) {
    const std::unique_lock lock(mutex_);
    const auto it = std::find_if(aliases_.begin(), aliases_.end(), [&](const auto& a) { return a->name == name; });
    if (it == aliases_.end()) return false;
    if ((*it)->built_in) {
      throw std::invalid_argument("friction law alias '" + std::string(name) + "' is built-in: only aliases "
                                  "added by register_law_alias() can be unregistered");
    }
    aliases_.erase(it);
    return true;
  }

  // A snapshot: entries stay alive while a caller makes laws from them, outside the lock.
  std::vector<std::shared_ptr<const Entry>> all() const {
    const std::shared_lock lock(mutex_);
    return entries_;
  }

  std::vector<std::shared_ptr<const Alias>> all_aliases() const {
    const std::shared_lock lock(mutex_);
    return aliases_;
  }

  // The law called `name`, or the alias called `name` (null if it is a law's name) and its law.
  std::pair<std::shared_ptr<const Entry>, std::shared_ptr<const Alias>> find(std::string_view name) const {
    const std::shared_lock lock(mutex_);
    if (auto e = find_locked(name)) return {e, nullptr};
    if (auto a = find_alias_locked(name)) {
      if (auto e = find_locked(a->target.name)) return {e, a};
    }
    std::string known;
    for (const auto& e : entries_) known += (known.empty() ? "" : ", ") + e->name;
    std::string aliases;
    for (const auto& a : aliases_) aliases += (aliases.empty() ? "" : ", ") + a->name + " (" + a->target.text + ")";
    throw std::invalid_argument("unknown friction law '" + std::string(name) + "'; known laws: " + known +
                                (aliases.empty() ? "" : "; aliases: " + aliases));
  }

 private:
  std::shared_ptr<const Entry> find_locked(std::string_view name) const {
    for (const auto& e : entries_) {
      if (e->name == name) return e;
    }
    return nullptr;
  }

  std::shared_ptr<const Alias> find_alias_locked(std::string_view name) const {
    for (const auto& a : aliases_) {
      if (a->name == name) return a;
    }
    return nullptr;
  }

  [[noreturn]] static void throw_taken(const std::string& name, const std::string& by) {
    throw std::invalid_argument("friction law '" + name + "' is already registered (" + by + "): choose another name");
  }

  void check_free_locked(const std::string& name) const {
    if (find_locked(name)) throw_taken(name, "as a law");
    if (const auto a = find_alias_locked(name)) throw_taken(name, "as an alias of '" + a->target.text + "'");
  }

  mutable std::shared_mutex mutex_;
  std::vector<std::shared_ptr<const Entry>> entries_;
  std::vector<std::shared_ptr<const Alias>> aliases_;
};

Registry& registry() {
  static Registry r;
  return r;
}

struct Resolved {
  std::shared_ptr<const Entry> entry;
  LawArguments args;
};

// ALIAS[:KEY=VALUE...] as the spec the alias stands for, with the given KEY=VALUE pairs after its
// own; the text stays the spec as given (echoed verbatim).
ParsedLawSpec expand_alias(const ParsedLawSpec& given, const Alias& alias) {
  ParsedLawSpec out = alias.target;
  out.text = given.text;
  for (const auto& kv : given.arguments) {
    const bool set = std::any_of(alias.target.arguments.begin(), alias.target.arguments.end(),
                                 [&](const auto& t) { return t.first == kv.first; });
    if (set) {
      throw std::invalid_argument("friction law spec '" + given.text + "': " + kv.first + " is set by the alias '" +
                                  alias.name + "', which stands for '" + alias.target.text +
                                  "': write the law's own name to choose " + kv.first);
    }
    out.arguments.push_back(kv);
  }
  return out;
}

Resolved resolve(std::string_view spec) {
  ParsedLawSpec parsed = parse_law_spec(spec);
  auto [entry, alias] = registry().find(parsed.name);
  if (alias) parsed = expand_alias(parsed, *alias);
  LawArguments args = bind_law_spec(parsed, entry->parameters);
  return {std::move(entry), std::move(args)};
}

LawInfo info_of(const Entry& e, const LawArguments& args) {
  const auto law = make_with(e, args);
  LawInfo info;
  info.name = e.name;
  info.spec = args.spec();
  info.summary = e.summary;
  info.parameters = e.parameters;
  for (const auto& a : registry().all_aliases()) {
    if (a->target.name == e.name) info.aliases.push_back({a->name, a->target.text});
  }
  info.reference = e.reference && args.canonical() == e.name;  // exact:pressure=uniform is not the reference
  info.slow = e.slow;
  info.has_poles = law->has_poles();
  info.promises = law->promises();
  return info;
}

}  // namespace

std::vector<LawInfo> list_laws() {
  std::vector<LawInfo> out;
  for (const auto& e : registry().all()) out.push_back(info_of(*e, LawArguments(e->name, e->parameters)));
  return out;
}

std::vector<std::string> list_law_specs() {
  std::vector<std::string> out;
  for (const auto& e : registry().all()) {
    out.push_back(e->name);
    for (const auto& p : e->parameters) {
      if (p.kind != LawParameter::Kind::choice) continue;
      for (const auto& c : p.choices) {
        if (c != p.default_value) out.push_back(e->name + ":" + p.key + "=" + c);
      }
    }
  }
  return out;
}

LawInfo law_info(std::string_view spec) {
  const Resolved r = resolve(spec);
  return info_of(*r.entry, r.args);
}

std::unique_ptr<FrictionLaw> make_law(std::string_view spec) {
  const Resolved r = resolve(spec);
  return make_with(*r.entry, r.args);
}

std::string canonical_law_spec(std::string_view spec) { return resolve(spec).args.canonical(); }

std::string reference_law_name() {
  for (const auto& e : registry().all()) {
    if (e->reference) return e->name;
  }
  throw std::logic_error("the registry has no reference law");
}

std::unique_ptr<FrictionLaw> make_reference_law() { return make_law(reference_law_name()); }

void register_law(LawRegistration registration) {
  const std::string& name = registration.name;
  check_law_declaration(name, registration.parameters);
  if (registration.summary.empty()) {
    throw std::invalid_argument("friction law '" + name + "' has no summary: give one line for `frictionlab laws`");
  }
  if (!registration.factory) throw std::invalid_argument("friction law '" + name + "' has no factory");
  Entry e{name, std::move(registration.summary), std::move(registration.parameters),
          std::move(registration.factory), /*reference=*/false, registration.facts.slow, /*built_in=*/false};
  // The law at its defaults, made once now (outside the lock): a factory that fails or makes
  // another law is reported here rather than at first use.
  try {
    (void)make_with(e, LawArguments(e.name, e.parameters));
  } catch (const std::logic_error& err) {
    throw std::invalid_argument(std::string(err.what()) + ": it cannot be registered");
  }
  registry().add(std::move(e));
}

void register_built_in_law(LawFactory factory, std::vector<LawParameter> parameters, LawFacts facts) {
  registry().add(built_in(std::move(factory), std::move(parameters), /*reference=*/false, facts.slow));
}

void register_law(std::string name, std::string summary, std::function<std::unique_ptr<FrictionLaw>()> factory) {
  LawRegistration r;
  r.name = std::move(name);
  r.summary = std::move(summary);
  if (factory) r.factory = [f = std::move(factory)](const LawArguments&) { return f(); };
  register_law(std::move(r));
}

bool unregister_law(std::string_view name) { return registry().remove(name); }

void register_law_alias(std::string alias, std::string spec) {
  Registry& r = registry();
  r.add_alias(r.make_alias(std::move(alias), spec, /*built_in=*/false));
}

bool unregister_law_alias(std::string_view alias) { return registry().remove_alias(alias); }

}  // namespace frictionlab::friction
