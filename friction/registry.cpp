#include "friction/registry.h"

#include <algorithm>
#include <mutex>
#include <shared_mutex>
#include <stdexcept>
#include <utility>

#include "friction/coulomb_decoupled_law.h"
#include "friction/exact_law.h"
#include "friction/exact_reference_law.h"
#include "friction/moller_ellipsoidal_law.h"
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
    add(built_in([](const LawArguments& a) {
          return std::make_unique<ExactReferenceLaw>(parse_pressure(a.choice("pressure")));
        },
                 ExactReferenceLaw::parameters(), false, /*slow=*/true));
    add(built_in([](const LawArguments&) { return std::make_unique<PadePrintedLaw>(PadeAlpha::major); }));
    add(built_in([](const LawArguments&) { return std::make_unique<PadePrintedLaw>(PadeAlpha::minor); }));
    add(built_in(plain<PadeReconstructedLaw>()));
    add(built_in(plain<MollerEllipsoidalLaw>()));
    add(built_in(plain<CoulombDecoupledLaw>()));
  }

  // Throws std::invalid_argument if the name is taken.
  void add(Entry e) {
    const std::unique_lock lock(mutex_);
    if (find_locked(e.name)) {
      throw std::invalid_argument("friction law '" + e.name + "' is already registered: choose another name");
    }
    entries_.push_back(std::make_shared<const Entry>(std::move(e)));
  }

  bool remove(std::string_view name) {
    const std::unique_lock lock(mutex_);
    const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e->name == name; });
    if (it == entries_.end()) return false;
    if ((*it)->built_in) {
      throw std::invalid_argument("friction law '" + std::string(name) + "' is built-in: only laws added by "
                                  "register_law() can be unregistered");
    }
    entries_.erase(it);
    return true;
  }

  // A snapshot: entries stay alive while a caller makes laws from them, outside the lock.
  std::vector<std::shared_ptr<const Entry>> all() const {
    const std::shared_lock lock(mutex_);
    return entries_;
  }

  std::shared_ptr<const Entry> find(std::string_view name) const {
    const std::shared_lock lock(mutex_);
    if (auto e = find_locked(name)) return e;
    std::string known;
    for (const auto& e : entries_) known += (known.empty() ? "" : ", ") + e->name;
    throw std::invalid_argument("unknown friction law '" + std::string(name) + "'; known laws: " + known);
  }

 private:
  std::shared_ptr<const Entry> find_locked(std::string_view name) const {
    for (const auto& e : entries_) {
      if (e->name == name) return e;
    }
    return nullptr;
  }

  mutable std::shared_mutex mutex_;
  std::vector<std::shared_ptr<const Entry>> entries_;
};

Registry& registry() {
  static Registry r;
  return r;
}

struct Resolved {
  std::shared_ptr<const Entry> entry;
  LawArguments args;
};

Resolved resolve(std::string_view spec) {
  const ParsedLawSpec parsed = parse_law_spec(spec);
  auto entry = registry().find(parsed.name);
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
  info.reference = e.reference;
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

void register_law(std::string name, std::string summary, std::function<std::unique_ptr<FrictionLaw>()> factory) {
  LawRegistration r;
  r.name = std::move(name);
  r.summary = std::move(summary);
  if (factory) r.factory = [f = std::move(factory)](const LawArguments&) { return f(); };
  register_law(std::move(r));
}

bool unregister_law(std::string_view name) { return registry().remove(name); }

}  // namespace frictionlab::friction
