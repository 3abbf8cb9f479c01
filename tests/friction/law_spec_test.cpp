// Law specs (friction/law_spec.h): the grammar of one spec and of a list of specs, parameter
// declarations, binding a spec to a law's parameters, and the canonical form.

#include "friction/law_spec.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace frictionlab::friction {
namespace law_spec_test {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The message of the std::invalid_argument `f` throws, or "" if it throws none.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Every fragment must appear in `message`.
void expect_mentions(const std::string& message, const std::vector<std::string>& fragments) {
  EXPECT_FALSE(message.empty()) << "no error";
  for (const auto& f : fragments) EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
}

// A law with one parameter of each kind, as a law's header would declare them.
std::vector<LawParameter> sample_parameters() {
  return {LawParameter::choice("pressure", {"hertz", "uniform", "punch"}, "hertz", "the pressure over the patch"),
          LawParameter::number("Rb", 0.0, true, kInf, false, "m", std::nullopt, "calibrated to the patch",
                               "torsional radius"),
          LawParameter::number("weight", 0.0, false, 1.0, false, "", 0.5, "", "a weight in [0, 1]")};
}

TEST(LawSpecParse, ANameAloneOrWithParametersInOrder) {
  const ParsedLawSpec plain = parse_law_spec("exact");
  EXPECT_EQ(plain.text, "exact");
  EXPECT_EQ(plain.name, "exact");
  EXPECT_TRUE(plain.arguments.empty());

  const ParsedLawSpec with = parse_law_spec("ellipsoidal:Rb=0.01,weight=1e-3");
  EXPECT_EQ(with.name, "ellipsoidal");
  ASSERT_EQ(with.arguments.size(), 2u);
  EXPECT_EQ(with.arguments[0].first, "Rb");
  EXPECT_EQ(with.arguments[0].second, "0.01");
  EXPECT_EQ(with.arguments[1].first, "weight");
  EXPECT_EQ(with.arguments[1].second, "1e-3");
}

TEST(LawSpecParse, EachSyntaxErrorNamesTheSpecAndWhatIsWrong) {
  struct Case {
    std::string spec;
    std::vector<std::string> mentions;
  };
  const Case cases[] = {
      {"", {"law spec = '' is invalid", "empty"}},
      {"exact:", {"'exact:'", "no parameters after ':'"}},
      {"exact:pressure", {"'exact:pressure'", "'pressure' has no value", "KEY=VALUE"}},
      {"exact:pressure=", {"'exact:pressure='", "'pressure' has an empty value"}},
      {"exact:=uniform", {"'exact:=uniform'", "empty key"}},
      {"exact:pressure=uniform,", {"'exact:pressure=uniform,'", "empty parameter"}},
      {"exact: pressure=uniform", {"white space"}},
      {"exact:pressure=a=b", {"'a=b'", "value"}},
      {"exact:pressure=a:b", {"'a:b'", "value"}},
      {"exa ct", {"white space"}},
      {"-exact", {"'-exact'", "name"}},
      {"exact:2x=1", {"'2x'", "key"}},
      {"a;b", {"'a;b'", "name"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.spec);
    expect_mentions(error_of([&] { (void)parse_law_spec(c.spec); }), c.mentions);
  }
}

TEST(LawSpecList, CommasSeparateLawsUnlessTheNextItemIsAParameter) {
  using V = std::vector<std::string>;
  EXPECT_EQ(split_law_list("exact"), V{"exact"});
  EXPECT_EQ(split_law_list("exact,pade-printed"), (V{"exact", "pade-printed"}));
  EXPECT_EQ(split_law_list("exact,exact:pressure=uniform,pade-printed"),
            (V{"exact", "exact:pressure=uniform", "pade-printed"}));
  EXPECT_EQ(split_law_list("ellipsoidal:Rb=0.01,weight=2,exact"), (V{"ellipsoidal:Rb=0.01,weight=2", "exact"}));
  // ';' always separates; spaces around items are dropped.
  EXPECT_EQ(split_law_list("ellipsoidal:Rb=0.01,weight=2;exact"), (V{"ellipsoidal:Rb=0.01,weight=2", "exact"}));
  EXPECT_EQ(split_law_list(" exact:pressure=punch , pade-printed ; coulomb-decoupled"),
            (V{"exact:pressure=punch", "pade-printed", "coulomb-decoupled"}));
  // A ':' before the '=' starts a new spec: its '=' belongs to that spec.
  EXPECT_EQ(split_law_list("exact:pressure=uniform,exact:pressure=punch"),
            (V{"exact:pressure=uniform", "exact:pressure=punch"}));
}

TEST(LawSpecList, BadListsNameTheList) {
  expect_mentions(error_of([] { (void)split_law_list(""); }), {"law list '' is empty"});
  expect_mentions(error_of([] { (void)split_law_list("exact,,pade-printed"); }),
                  {"'exact,,pade-printed'", "empty item"});
  expect_mentions(error_of([] { (void)split_law_list("exact;"); }), {"'exact;'", "empty item"});
  expect_mentions(error_of([] { (void)split_law_list("pressure=uniform,exact"); }),
                  {"'pressure=uniform,exact'", "starts with the parameter 'pressure=uniform'"});
  expect_mentions(error_of([] { (void)split_law_list("exact;pressure=uniform"); }),
                  {"'pressure=uniform'", "';'"});
}

TEST(LawSpecBind, DefaultsFillWhatTheSpecOmits) {
  const LawArguments args = bind_law_spec(parse_law_spec("law:Rb=0.02"), sample_parameters());
  EXPECT_EQ(args.spec(), "law:Rb=0.02");
  EXPECT_EQ(args.name(), "law");
  EXPECT_EQ(args.choice("pressure"), "hertz");
  ASSERT_TRUE(args.number("Rb").has_value());
  EXPECT_EQ(*args.number("Rb"), 0.02);
  EXPECT_EQ(args.number("weight"), 0.5);
  EXPECT_TRUE(args.given("Rb"));
  EXPECT_FALSE(args.given("pressure"));

  const LawArguments none = bind_law_spec(parse_law_spec("law"), sample_parameters());
  EXPECT_FALSE(none.number("Rb").has_value());  // no default: the law calibrates it itself
  const LawArguments defaults("law", sample_parameters());
  EXPECT_EQ(defaults.spec(), "law");
  EXPECT_EQ(defaults.choice("pressure"), "hertz");
  EXPECT_FALSE(defaults.number("Rb").has_value());
}

TEST(LawSpecBind, NumbersTakeTheFullDoubleRangeOfTheirRule) {
  const auto params = sample_parameters();
  EXPECT_EQ(*bind_law_spec(parse_law_spec("law:Rb=1e-300"), params).number("Rb"), 1e-300);
  EXPECT_EQ(*bind_law_spec(parse_law_spec("law:Rb=+2.5E3"), params).number("Rb"), 2500.0);
  EXPECT_EQ(*bind_law_spec(parse_law_spec("law:weight=0"), params).number("weight"), 0.0);  // closed end
  EXPECT_EQ(*bind_law_spec(parse_law_spec("law:weight=1"), params).number("weight"), 1.0);
}

TEST(LawSpecBind, EachBadArgumentNamesSpecKeyValueAndRule) {
  const auto params = sample_parameters();
  struct Case {
    std::string spec;
    std::vector<std::string> mentions;
  };
  const Case cases[] = {
      {"law:pressure=flat",
       {"law spec = 'law:pressure=flat' is invalid", "pressure = 'flat'", "one of hertz, uniform, punch"}},
      {"law:n=1", {"'law:n=1'", "law has no parameter 'n'", "its parameters: pressure, Rb, weight"}},
      {"law:pressure=hertz,pressure=punch", {"'law:pressure=hertz,pressure=punch'", "pressure is given twice"}},
      {"law:Rb=0", {"'law:Rb=0'", "Rb = '0'", "a finite number in (0, inf) m"}},
      {"law:Rb=-1", {"Rb = '-1'", "(0, inf) m"}},
      {"law:Rb=abc", {"Rb = 'abc'", "(0, inf) m"}},
      {"law:Rb=1e999", {"Rb = '1e999'", "(0, inf) m"}},
      {"law:Rb=nan", {"Rb = 'nan'", "finite number"}},
      {"law:Rb=inf", {"Rb = 'inf'", "finite number"}},
      {"law:Rb=0x10", {"Rb = '0x10'"}},
      {"law:Rb=1.0.0", {"Rb = '1.0.0'"}},
      {"law:weight=1.5", {"weight = '1.5'", "[0, 1]"}},
      {"law:Pressure=hertz", {"no parameter 'Pressure'"}},  // keys are case-sensitive
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.spec);
    expect_mentions(error_of([&] { (void)bind_law_spec(parse_law_spec(c.spec), params); }), c.mentions);
  }
  expect_mentions(error_of([] { (void)bind_law_spec(parse_law_spec("plain:x=1"), {}); }),
                  {"'plain:x=1'", "plain has no parameters"});
}

TEST(LawSpecBind, ACanonicalFormDropsDefaultsAndNormalisesNumbers) {
  const auto params = sample_parameters();
  const auto canonical = [&](const std::string& s) { return bind_law_spec(parse_law_spec(s), params).canonical(); };
  EXPECT_EQ(canonical("law"), "law");
  EXPECT_EQ(canonical("law:pressure=hertz"), "law");
  EXPECT_EQ(canonical("law:weight=0.5"), "law");
  EXPECT_EQ(canonical("law:weight=2.5e-1,pressure=punch,Rb=1.50"), "law:pressure=punch,Rb=1.5,weight=0.25");
  EXPECT_EQ(canonical("law:Rb=0.1"), "law:Rb=0.1");
  EXPECT_EQ(canonical("law:Rb=+1E-2"), "law:Rb=0.01");
  EXPECT_EQ(canonical("law:Rb=0.30000000000000004"), "law:Rb=0.30000000000000004");  // every bit kept
}

TEST(LawSpecFileStem, IsSafeInPathsAndLinks) {
  EXPECT_EQ(law_file_stem("exact"), "exact");
  EXPECT_EQ(law_file_stem("exact:pressure=uniform"), "exact_pressure-uniform");
  EXPECT_EQ(law_file_stem("ellipsoidal:Rb=0.01,x=2"), "ellipsoidal_Rb-0.01_x-2");
}

TEST(LawSpecBind, AskingForAnUndeclaredParameterIsALogicError) {
  const LawArguments args("law", sample_parameters());
  EXPECT_THROW((void)args.choice("Rb"), std::logic_error);  // a number, not a choice
  EXPECT_THROW((void)args.number("pressure"), std::logic_error);
  EXPECT_THROW((void)args.number("other"), std::logic_error);
}

TEST(LawSpecDeclaration, BadDeclarationsAreRejected) {
  EXPECT_EQ(error_of([] { check_law_declaration("my-law_2.b", sample_parameters()); }), "");
  expect_mentions(error_of([] { check_law_declaration("my:law", {}); }), {"'my:law'", "name"});
  expect_mentions(error_of([] { check_law_declaration("", {}); }), {"empty"});
  expect_mentions(error_of([] {
                    check_law_declaration("x", {LawParameter::choice("p", {"a"}, "a", "d"),
                                                LawParameter::choice("p", {"b"}, "b", "d")});
                  }),
                  {"parameter 'p' is declared twice"});
  expect_mentions(error_of([] { check_law_declaration("x", {LawParameter::choice("p", {}, "", "d")}); }),
                  {"'p'", "no choices"});
  expect_mentions(error_of([] { check_law_declaration("x", {LawParameter::choice("p", {"a", "b,c"}, "a", "d")}); }),
                  {"'b,c'"});
  expect_mentions(error_of([] { check_law_declaration("x", {LawParameter::choice("p", {"a"}, "z", "d")}); }),
                  {"default 'z'", "one of a"});
  expect_mentions(error_of([] {
                    check_law_declaration("x", {LawParameter::number("r", 1.0, false, 0.0, false, "m", std::nullopt,
                                                                     "auto", "d")});
                  }),
                  {"'r'", "range"});
  expect_mentions(error_of([] {
                    check_law_declaration("x", {LawParameter::number("r", 0.0, true, 1.0, false, "m", 0.0, "", "d")});
                  }),
                  {"default '0'", "(0, 1] m"});
  expect_mentions(error_of([] {
                    check_law_declaration("x", {LawParameter::number("r", 0.0, true, 1.0, false, "m", std::nullopt,
                                                                     "", "d")});
                  }),
                  {"'r'", "no default", "say what the law does without it"});
}

TEST(LawSpecDeclaration, DescribesEachParameterOnOneLine) {
  const auto params = sample_parameters();
  EXPECT_EQ(params[0].describe(), "pressure = hertz|uniform|punch (default hertz): the pressure over the patch");
  EXPECT_EQ(params[1].describe(), "Rb = a finite number in (0, inf) m (default: calibrated to the patch): torsional radius");
  EXPECT_EQ(params[2].describe(), "weight = a finite number in [0, 1] (default 0.5): a weight in [0, 1]");
}

}  // namespace
}  // namespace frictionlab::friction
