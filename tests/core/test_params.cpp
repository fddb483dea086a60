// Parameter declarations: one declaration gives the spec, the default, validation and the
// filled field; nothing is read back by a second spelling of a name.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/params.h"

namespace agv {
namespace {

enum class Mode { fast, careful };

struct Inner {
  double step = 0.0;
  int points = 0;
};

struct Options {
  double weight = 0.0;
  long long budget = 0;
  bool verbose = false;
  Mode mode = Mode::fast;
  Inner inner;
};

ParamDecls<Inner> inner_decls() {
  ParamDecls<Inner> d;
  d.number("step", &Inner::step, 0.25, 0.01, 1.0, "sample step")
      .integer("points", &Inner::points, 10, 2, 100, "samples");
  return d;
}

ParamDecls<Options> decls() {
  ParamDecls<Options> d;
  d.number("weight", &Options::weight, 1.5, 1.0, 10.0, "heuristic weight")
      .integer("budget", &Options::budget, 500, 1, 1000000, "iterations")
      .boolean("verbose", &Options::verbose, false, "say more")
      .choice("mode", &Options::mode, Mode::careful,
              ChoiceTable<Mode>{{"fast", Mode::fast}, {"careful", Mode::careful}}, "how")
      .include(&Options::inner, inner_decls());
  return d;
}

TEST(ParamDecls, DefaultsFillEveryField) {
  const Options o = decls().resolve(nlohmann::json::object(), "p");
  EXPECT_DOUBLE_EQ(o.weight, 1.5);
  EXPECT_EQ(o.budget, 500);
  EXPECT_FALSE(o.verbose);
  EXPECT_EQ(o.mode, Mode::careful);
  EXPECT_DOUBLE_EQ(o.inner.step, 0.25);
  EXPECT_EQ(o.inner.points, 10);
  EXPECT_EQ(decls().specs().size(), 6u);
  EXPECT_EQ(decls().specs()[3].default_value, "careful");
}

TEST(ParamDecls, GivenValuesReachTheirFields) {
  const Options o = decls().resolve({{"weight", 2},
                                     {"budget", 7.0},
                                     {"verbose", true},
                                     {"mode", "fast"},
                                     {"points", 3},
                                     {"step", 0.5}},
                                    "p");
  EXPECT_DOUBLE_EQ(o.weight, 2.0);
  EXPECT_EQ(o.budget, 7);
  EXPECT_TRUE(o.verbose);
  EXPECT_EQ(o.mode, Mode::fast);
  EXPECT_EQ(o.inner.points, 3);
  EXPECT_DOUBLE_EQ(o.inner.step, 0.5);
}

TEST(ParamDecls, ErrorsNameTheField) {
  auto message = [](const nlohmann::json& given) {
    try {
      decls().resolve(given, "planners[2].params");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({{"wieght", 2}}).find("planners[2].params.wieght: unknown parameter"),
            std::string::npos);
  EXPECT_NE(message({{"weight", 0.5}}).find("planners[2].params.weight"), std::string::npos);
  EXPECT_NE(message({{"mode", "slow"}}).find("not one of: fast, careful"), std::string::npos);
  EXPECT_NE(message({{"points", 1.5}}).find("expected an integer"), std::string::npos);
  EXPECT_NE(message({{"verbose", 1}}).find("expected true or false"), std::string::npos);
}

TEST(ParamDecls, ANameDeclaredTwiceIsABug) {
  ParamDecls<Options> d;
  d.number("weight", &Options::weight, 1.0, 0.0, 2.0, "w");
  EXPECT_THROW(d.number("weight", &Options::weight, 1.0, 0.0, 2.0, "w"), std::logic_error);
  EXPECT_THROW(d.choice("mode", &Options::mode, Mode::fast,
                        ChoiceTable<Mode>{{"careful", Mode::careful}}, "default not listed"),
               std::logic_error);
}

// The declarations a plugin hands over are checked when it loads (engine/plan/plugins.cpp): each
// malformed one is refused with its name and what is wrong; every built-in declaration passes.
std::string refusal(std::vector<ParamSpec> specs) {
  try {
    check_param_specs(specs, "plugin p: planner q");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ParamSpecCheck, RefusesEachMalformedDeclarationNamingIt) {
  const ParamSpec good = ParamSpec::number("w", 0.5, 0.0, 1.0, "");
  EXPECT_EQ(refusal({good, ParamSpec::integer("n", 3, 1, 9, ""), ParamSpec::boolean("b", true, ""),
                     ParamSpec::choice("c", "a", {"a", "b"}, "")}),
            "");
  struct Case {
    std::vector<ParamSpec> specs;
    std::string says;
  };
  ParamSpec bad_type = good;
  bad_type.type = static_cast<ParamType>(7);
  ParamSpec nan_bound = good;
  nan_bound.max = std::nan("");
  ParamSpec stray_choices = good;
  stray_choices.choices = {"x"};
  ParamSpec text_default = good;
  text_default.default_value = "high";
  const Case cases[] = {
      {{ParamSpec::number("", 1, 0, 2, "")}, "parameter \"\": a name must be a word"},
      {{ParamSpec::number("Weight", 1, 0, 2, "")}, "parameter \"Weight\": a name must be a word"},
      {{good, good}, "parameter \"w\": declared twice"},
      {{bad_type}, "parameter \"w\": unknown type 7"},
      {{nan_bound}, "parameter \"w\": a bound is NaN"},
      {{ParamSpec::integer("n", 3, 5, 1, "")}, "parameter \"n\": its range [5, 1] is empty"},
      {{ParamSpec::number("w", 5, 0, 1, "")}, "parameter \"w\" default: 5.0 is outside [0, 1]"},
      {{text_default}, "parameter \"w\" default: expected a number, got \"high\""},
      {{ParamSpec::choice("c", "a", {}, "")}, "parameter \"c\": a choice without choices"},
      {{ParamSpec::choice("c", "a", {"a", "a"}, "")}, "parameter \"c\": choice \"a\" listed twice"},
      {{ParamSpec::choice("c", "z", {"a", "b"}, "")},
       "parameter \"c\" default: \"z\" is not one of: a, b"},
      {{stray_choices}, "parameter \"w\": choices given for a parameter that is not a choice"},
  };
  for (const Case& c : cases) {
    const std::string text = refusal(c.specs);
    EXPECT_NE(text.find("plugin p: planner q: " + c.says), std::string::npos)
        << "expected \"" << c.says << "\", got \"" << text << "\"";
  }
}

}  // namespace
}  // namespace agv
