// The registry by spec (friction/registry.h): laws made from specs know their spec, bad specs name
// what is wrong, user code registers its own laws (thread-safe, no edit of the registry), and
// aliases are other names of a law (or of one of its specs), listed once, with the law.

#include "friction/registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "friction/reference_laws.h"

namespace frictionlab::friction {
namespace registry_test {

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

void expect_mentions(const std::string& message, const std::vector<std::string>& fragments) {
  EXPECT_FALSE(message.empty()) << "no error";
  for (const auto& f : fragments) EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
}

// A user's law: pure Coulomb sliding friction scaled by `gain` (a number parameter), no moment.
class ScaledSlidingLaw final : public FrictionLaw {
 public:
  ScaledSlidingLaw(std::string name, double gain) : name_(std::move(name)), gain_(gain) {}
  [[nodiscard]] std::string_view name() const override { return name_; }
  [[nodiscard]] std::string_view summary() const override { return "test law: kN gain along the slip"; }

 private:
  [[nodiscard]] FrictionForces do_evaluate(const ContactInput& in) const override {
    return {in.U > 0.0 ? gain_ * in.k * in.N : 0.0, 0.0, 0.0};
  }
  std::string name_;
  double gain_;
};

LawRegistration scaled_law(const std::string& name) {
  LawRegistration r;
  r.name = name;
  r.summary = "test law: kN gain along the slip";
  r.parameters = {LawParameter::number("gain", 0.0, false, 1.0, false, "", 1.0, "", "fraction of kN"),
                  LawParameter::choice("mode", {"plain", "fancy"}, "plain", "unused")};
  r.factory = [name](const LawArguments& args) { return std::make_unique<ScaledSlidingLaw>(name, *args.number("gain")); };
  return r;
}

// Registers on construction, unregisters on destruction: each test leaves the registry as found.
struct Registered {
  std::string name;
  explicit Registered(LawRegistration r) : name(r.name) { register_law(std::move(r)); }
  ~Registered() { (void)unregister_law(name); }
};

bool listed(const std::string& name) {
  const auto laws = list_laws();
  return std::any_of(laws.begin(), laws.end(), [&](const LawInfo& i) { return i.name == name; });
}

// exact-reference needs GSL (GPL-3): frictionlab::friction does not register it; its own library
// does, once, as a built-in law (the first test of this file: nothing registered it before).
TEST(RegistryReference, TheGslReferenceLawComesWithItsOwnLibrary) {
  EXPECT_THROW((void)make_law("exact-reference"), std::invalid_argument);
  const std::size_t before = list_laws().size();
  register_reference_laws();
  register_reference_laws();  // a second call does nothing
  EXPECT_EQ(list_laws().size(), before + 1);
  const LawInfo info = law_info("exact-reference:pressure=uniform");
  EXPECT_TRUE(info.slow);
  EXPECT_FALSE(info.reference);
  EXPECT_EQ(make_law("exact-reference")->name(), "exact-reference");
  EXPECT_THROW((void)unregister_law("exact-reference"), std::invalid_argument) << "built in";
}

TEST(RegistrySpec, ALawKnowsTheSpecItWasMadeFromVerbatim) {
  const auto plain = make_law("exact");
  EXPECT_EQ(plain->name(), "exact");
  EXPECT_EQ(plain->spec(), "exact");
  const auto hertz = make_law("exact:pressure=hertz");
  EXPECT_EQ(hertz->name(), "exact");
  EXPECT_EQ(hertz->spec(), "exact:pressure=hertz");
  EXPECT_EQ(canonical_law_spec("exact:pressure=hertz"), "exact");
  const LawInfo info = law_info("exact:pressure=hertz");
  EXPECT_EQ(info.name, "exact");
  EXPECT_EQ(info.spec, "exact:pressure=hertz");
  EXPECT_TRUE(info.reference);
  EXPECT_FALSE(law_info("exact:pressure=uniform").reference);  // another law than the reference
}

TEST(RegistrySpec, TheExactLawDeclaresItsPressure) {
  const LawInfo info = law_info("exact");
  ASSERT_FALSE(info.parameters.empty());
  EXPECT_EQ(info.parameters[0].key, "pressure");
  EXPECT_EQ(info.parameters[0].default_value, "hertz");
  for (const auto& law : list_laws()) EXPECT_EQ(law.spec, law.name);
}

TEST(RegistrySpec, BadSpecsNameTheSpecKeyValueAndRule) {
  expect_mentions(error_of([] { (void)make_law("nope:x=1"); }), {"unknown friction law 'nope'", "known laws: exact"});
  expect_mentions(error_of([] { (void)make_law("exact:pressure=flat"); }),
                  {"'exact:pressure=flat'", "pressure = 'flat'", "one of hertz"});
  expect_mentions(error_of([] { (void)make_law("exact:n=1"); }),
                  {"'exact:n=1'", "exact has no parameter 'n'", "its parameters: pressure"});
  expect_mentions(error_of([] { (void)make_law("exact:pressure=hertz,pressure=hertz"); }), {"pressure is given twice"});
  expect_mentions(error_of([] { (void)make_law("pade-printed:alpha=minor"); }),
                  {"'pade-printed:alpha=minor'", "pade-printed has no parameters"});
  expect_mentions(error_of([] { (void)law_info("exact:"); }), {"'exact:'"});
  expect_mentions(error_of([] { (void)canonical_law_spec("exact:pressure=flat"); }), {"'flat'"});
}

TEST(RegistryRegistration, AUserLawIsMadeByItsSpecAndListedWithItsParameters) {
  const Registered reg(scaled_law("test-scaled"));
  ASSERT_TRUE(listed("test-scaled"));
  EXPECT_EQ(list_laws().front().name, "exact");  // the reference stays first

  const auto law = make_law("test-scaled:gain=0.25");
  EXPECT_EQ(law->name(), "test-scaled");
  EXPECT_EQ(law->spec(), "test-scaled:gain=0.25");
  const FrictionForces f = law->evaluate({1.0, 0.0, 1.0, 1.0, 0.0, 8.0, 0.5});
  EXPECT_EQ(f.F1, 0.25 * 0.5 * 8.0);
  EXPECT_EQ(make_law("test-scaled")->evaluate({1.0, 0.0, 1.0, 1.0, 0.0, 8.0, 0.5}).F1, 4.0);  // default gain 1

  const LawInfo info = law_info("test-scaled:gain=0.5");
  EXPECT_EQ(info.summary, "test law: kN gain along the slip");
  ASSERT_EQ(info.parameters.size(), 2u);
  EXPECT_EQ(info.parameters[0].key, "gain");
  EXPECT_FALSE(info.reference);
  expect_mentions(error_of([] { (void)make_law("test-scaled:gain=2"); }), {"gain = '2'", "[0, 1]"});
  // Its choice parameter's other value is a variant the soundness tests would run.
  const auto specs = list_law_specs();
  EXPECT_NE(std::find(specs.begin(), specs.end(), "test-scaled:mode=fancy"), specs.end());
  EXPECT_NE(std::find(specs.begin(), specs.end(), "test-scaled"), specs.end());
}

TEST(RegistryRegistration, ClashesAndBadRegistrationsAreErrors) {
  expect_mentions(error_of([] { register_law(scaled_law("exact")); }), {"'exact'", "already registered"});
  {
    const Registered reg(scaled_law("test-twice"));
    expect_mentions(error_of([] { register_law(scaled_law("test-twice")); }), {"'test-twice'", "already registered"});
  }
  EXPECT_FALSE(listed("test-twice"));
  LawRegistration no_factory = scaled_law("test-no-factory");
  no_factory.factory = nullptr;
  expect_mentions(error_of([&] { register_law(no_factory); }), {"'test-no-factory'", "no factory"});
  LawRegistration no_summary = scaled_law("test-no-summary");
  no_summary.summary.clear();
  expect_mentions(error_of([&] { register_law(no_summary); }), {"'test-no-summary'", "summary"});
  expect_mentions(error_of([] { register_law(scaled_law("bad name")); }), {"'bad name'"});
  EXPECT_FALSE(unregister_law("test-never-registered"));
  expect_mentions(error_of([] { (void)unregister_law("exact"); }), {"'exact'", "built-in"});
}

TEST(RegistryRegistration, AFactoryThatMakesAnotherLawIsRejectedAtRegistration) {
  LawRegistration r = scaled_law("test-misnamed");
  r.factory = [](const LawArguments&) { return std::make_unique<ScaledSlidingLaw>("something-else", 1.0); };
  expect_mentions(error_of([&] { register_law(r); }), {"'test-misnamed'", "made a law named 'something-else'"});
  r.factory = [](const LawArguments&) { return std::unique_ptr<FrictionLaw>(); };
  expect_mentions(error_of([&] { register_law(r); }), {"'test-misnamed'", "made no law"});
  EXPECT_FALSE(listed("test-misnamed"));
}

TEST(RegistryRegistration, ConcurrentRegistrationAndUseAreSafe) {
  // Four threads register laws while four others list and make laws: every law ends registered
  // once, and nothing races (ASan/TSan builds would flag it; here: no crash, consistent counts).
  const std::size_t before = list_laws().size();
  constexpr int kPerThread = 25;
  std::atomic<bool> failed{false};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([t, &failed] {
      for (int i = 0; i < kPerThread; ++i) {
        try {
          register_law(scaled_law("test-concurrent-" + std::to_string(t) + "-" + std::to_string(i)));
        } catch (...) {
          failed = true;
        }
      }
    });
    threads.emplace_back([&failed] {
      for (int i = 0; i < kPerThread; ++i) {
        try {
          if (make_law("exact")->name() != "exact" || list_laws().empty()) failed = true;
        } catch (...) {
          failed = true;
        }
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_FALSE(failed);
  EXPECT_EQ(list_laws().size(), before + 4 * kPerThread);
  for (int t = 0; t < 4; ++t) {
    for (int i = 0; i < kPerThread; ++i) EXPECT_TRUE(unregister_law("test-concurrent-" + std::to_string(t) + "-" + std::to_string(i)));
  }
  EXPECT_EQ(list_laws().size(), before);
}

// A seeded set of contacts that slip and spin (s log-uniform in [1e-3, 1e3], mu in [0.05, 1], all
// psi, both signs of Omega), plus pure spin and pure slip: two laws that agree bit for bit on all
// of them are, for a listing, the same law.
std::vector<ContactInput> probe_contacts() {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> log_s(-3.0, 3.0), mu(0.05, 1.0), psi(0.0, std::numbers::pi);
  std::vector<ContactInput> out;
  for (int i = 0; i < 64; ++i) {
    const double Omega = (i % 2 == 0) ? 3.0 : -3.0;
    const double a = 0.004;
    out.push_back({std::pow(10.0, log_s(rng)) * a * 3.0, Omega, a, mu(rng) * a, psi(rng), 12.0, 0.3});
  }
  out.push_back({0.0, 5.0, 0.004, 0.002, 0.4, 12.0, 0.3});
  out.push_back({0.2, 0.0, 0.004, 0.002, 0.4, 12.0, 0.3});
  return out;
}

// Forces, or NaN for all three where the law refuses the input (a pole of the printed law).
FrictionForces forces_or_nan(const FrictionLaw& law, const ContactInput& in) {
  try {
    return law.evaluate(in);
  } catch (const std::invalid_argument&) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
}

bool same_bits(double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); }

bool same_bits(const FrictionLaw& a, const FrictionLaw& b, const std::vector<ContactInput>& set) {
  for (const auto& in : set) {
    const FrictionForces f = forces_or_nan(a, in);
    const FrictionForces g = forces_or_nan(b, in);
    if (!same_bits(f.F1, g.F1) || !same_bits(f.F2, g.F2) || !same_bits(f.M, g.M)) return false;
  }
  return true;
}

const LawInfo* find_listed(const std::vector<LawInfo>& laws, const std::string& name) {
  const auto it = std::find_if(laws.begin(), laws.end(), [&](const LawInfo& i) { return i.name == name; });
  return it == laws.end() ? nullptr : &*it;
}

bool has_alias(const LawInfo& info, const std::string& alias, const std::string& spec) {
  return std::any_of(info.aliases.begin(), info.aliases.end(),
                     [&](const LawAlias& a) { return a.name == alias && a.spec == spec; });
}

TEST(RegistryAlias, AListingHasNoDuplicateLaw) {
  // Every "all laws" set (the studies, the benchmark, Python's laws()) is built from list_laws():
  // no two of its entries may be one law under two names, i.e. compute the same forces bit for
  // bit on a generic set of contacts, or share a canonical spec.
  const auto laws = list_laws();
  const auto set = probe_contacts();
  for (std::size_t i = 0; i < laws.size(); ++i) {
    if (laws[i].slow) continue;  // the quadrature cross-check differs from exact in the last bits anyway
    const auto li = make_law(laws[i].spec);
    for (std::size_t j = 0; j < i; ++j) {
      if (laws[j].slow) continue;
      EXPECT_NE(canonical_law_spec(laws[i].spec), canonical_law_spec(laws[j].spec));
      EXPECT_FALSE(same_bits(*li, *make_law(laws[j].spec), set))
          << laws[i].spec << " and " << laws[j].spec << " are the same law: one should be an alias of the other";
    }
  }
}

TEST(RegistryAlias, TheOldNamesAreAliasesListedWithTheirLaw) {
  const auto laws = list_laws();
  EXPECT_EQ(find_listed(laws, "moller-ellipsoidal"), nullptr);
  EXPECT_EQ(find_listed(laws, "coulomb-decoupled"), nullptr);
  const LawInfo* ellipsoidal = find_listed(laws, "ellipsoidal");
  const LawInfo* decoupled = find_listed(laws, "decoupled");
  ASSERT_NE(ellipsoidal, nullptr);
  ASSERT_NE(decoupled, nullptr);
  EXPECT_TRUE(has_alias(*ellipsoidal, "moller-ellipsoidal", "ellipsoidal"));
  EXPECT_TRUE(has_alias(*decoupled, "coulomb-decoupled", "decoupled"));
  EXPECT_TRUE(find_listed(laws, "exact")->aliases.empty());
  const auto specs = list_law_specs();
  EXPECT_EQ(std::count(specs.begin(), specs.end(), "moller-ellipsoidal"), 0);
  EXPECT_EQ(std::count(specs.begin(), specs.end(), "coulomb-decoupled"), 0);
}

TEST(RegistryAlias, AnAliasMakesTheSameLawAsItsTargetBitForBit) {
  const auto set = probe_contacts();
  for (const auto& [alias, target] : std::vector<std::pair<std::string, std::string>>{
           {"moller-ellipsoidal", "ellipsoidal"}, {"coulomb-decoupled", "decoupled"}}) {
    SCOPED_TRACE(alias);
    const auto law = make_law(alias);
    EXPECT_EQ(law->name(), target);
    EXPECT_EQ(law->spec(), alias);  // echoed verbatim in outputs
    EXPECT_TRUE(same_bits(*law, *make_law(target), set));
    EXPECT_EQ(canonical_law_spec(alias), target);
    const LawInfo info = law_info(alias);
    EXPECT_EQ(info.name, target);
    EXPECT_EQ(info.spec, alias);
    EXPECT_EQ(info.summary, law_info(target).summary);
  }
  // An alias takes the parameters of its target: the same law as the target's spec.
  const auto fixed = make_law("moller-ellipsoidal:Rb=0.0021");
  EXPECT_EQ(fixed->spec(), "moller-ellipsoidal:Rb=0.0021");
  EXPECT_TRUE(same_bits(*fixed, *make_law("ellipsoidal:Rb=0.0021"), set));
  EXPECT_EQ(canonical_law_spec("coulomb-decoupled:r_spin=0"), "decoupled:r_spin=0");
}

TEST(RegistryAlias, AUserAliasStandsForASpecEverywhereANameDoes) {
  register_law_alias("test-flat-face", "exact:pressure=uniform");
  const auto set = probe_contacts();
  const auto law = make_law("test-flat-face");
  EXPECT_EQ(law->spec(), "test-flat-face");
  EXPECT_EQ(law->name(), "exact");
  EXPECT_TRUE(same_bits(*law, *make_law("exact:pressure=uniform"), set));
  EXPECT_EQ(canonical_law_spec("test-flat-face"), "exact:pressure=uniform");
  EXPECT_FALSE(law_info("test-flat-face").reference);  // the uniform variant is not the reference
  EXPECT_TRUE(has_alias(*find_listed(list_laws(), "exact"), "test-flat-face", "exact:pressure=uniform"));
  // The alias fixes the pressure: setting it again is an error naming the key and the alias.
  expect_mentions(error_of([] { (void)make_law("test-flat-face:pressure=punch"); }),
                  {"'test-flat-face:pressure=punch'", "pressure", "'test-flat-face'", "exact:pressure=uniform"});
  EXPECT_TRUE(unregister_law_alias("test-flat-face"));
  EXPECT_FALSE(unregister_law_alias("test-flat-face"));
  expect_mentions(error_of([] { (void)make_law("test-flat-face"); }), {"unknown friction law 'test-flat-face'"});
  EXPECT_FALSE(has_alias(*find_listed(list_laws(), "exact"), "test-flat-face", "exact:pressure=uniform"));
}

TEST(RegistryAlias, TheAliasesOfAUserLawGoWithIt) {
  register_law(scaled_law("test-aliased"));
  register_law_alias("test-aliased-old", "test-aliased");
  expect_mentions(error_of([] { register_law(scaled_law("test-aliased-old")); }), {"'test-aliased-old'", "alias"});
  EXPECT_EQ(make_law("test-aliased-old:gain=0.5")->evaluate({1.0, 0.0, 1.0, 1.0, 0.0, 8.0, 0.5}).F1, 2.0);
  EXPECT_TRUE(has_alias(*find_listed(list_laws(), "test-aliased"), "test-aliased-old", "test-aliased"));
  EXPECT_TRUE(unregister_law("test-aliased"));  // its aliases go with it
  expect_mentions(error_of([] { (void)make_law("test-aliased-old"); }), {"unknown friction law 'test-aliased-old'"});
  // The name is free again.
  register_law_alias("test-aliased-old", "exact");
  EXPECT_TRUE(unregister_law_alias("test-aliased-old"));
}

TEST(RegistryAlias, BadAliasesAreErrorsNamingThem) {
  // A target that is not a law, or not a valid spec of one.
  expect_mentions(error_of([] { register_law_alias("test-alias", "nope"); }),
                  {"'test-alias'", "unknown friction law 'nope'"});
  expect_mentions(error_of([] { register_law_alias("test-alias", "exact:pressure=flat"); }),
                  {"'test-alias'", "pressure = 'flat'"});
  // An alias of an alias: name the law itself.
  expect_mentions(error_of([] { register_law_alias("test-alias", "moller-ellipsoidal"); }),
                  {"'test-alias'", "'moller-ellipsoidal' is an alias", "ellipsoidal"});
  // Names already taken, by a law or an alias, built-in or registered.
  expect_mentions(error_of([] { register_law_alias("exact", "pade-printed"); }), {"'exact'", "already"});
  expect_mentions(error_of([] { register_law_alias("moller-ellipsoidal", "exact"); }),
                  {"'moller-ellipsoidal'", "already"});
  expect_mentions(error_of([] { register_law(scaled_law("coulomb-decoupled")); }), {"'coulomb-decoupled'", "alias"});
  // Names that break the grammar; built-in aliases stay.
  expect_mentions(error_of([] { register_law_alias("bad alias", "exact"); }), {"'bad alias'"});
  expect_mentions(error_of([] { register_law_alias("test-alias", ""); }), {"'test-alias'"});
  expect_mentions(error_of([] { (void)unregister_law_alias("coulomb-decoupled"); }), {"'coulomb-decoupled'", "built-in"});
  EXPECT_FALSE(unregister_law_alias("test-alias"));
  EXPECT_EQ(make_law("coulomb-decoupled")->name(), "decoupled");
}

}  // namespace
}  // namespace frictionlab::friction
