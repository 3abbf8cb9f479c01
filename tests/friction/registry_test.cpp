// The registry by spec (friction/registry.h): laws made from specs know their spec, bad specs name
// what is wrong, and user code registers its own laws (thread-safe, no edit of the registry).

#include "friction/registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace frictionlab::friction {
namespace {

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

}  // namespace
}  // namespace frictionlab::friction
