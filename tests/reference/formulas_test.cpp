// Each law's formula, as students read it, against the law's code in the reference physics
// (grader/reference/physics.inc): the formula evaluated on random inputs gives the code's value,
// and every text a student reads about the law (the handout, the starter, the headers, the
// viewer) holds the formula word for word (blanks aside). A law changed in the code and not in
// its formula, or in the formula and not in a text students read, fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "a6/force_model.h"
#include "formula.h"

namespace a6::test {
namespace {
#include A6_FORCE_MODELS  // the reference physics

// Random inputs, the same each run.
struct Draw {
  std::mt19937_64 engine{20261203};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(engine); }
  Vec2 vec(double r) { return {uniform(-r, r), uniform(-r, r)}; }
};

// One law: its formula, the texts students read it in, and a draw of inputs as the formula's
// symbols with the value the reference's code gives for them.
struct Law {
  const char* name;
  const char* formula;
  std::vector<const char*> readers;  ///< files, from the repository's root
  std::function<std::pair<Bindings, Value>(Draw&)> draw;
};

// A spring with random ends and constants: the symbols of its laws, its force and Jacobians.
struct SpringDraw {
  Bindings symbols;
  Value force;
  SpringJacobians jacobians;
};

SpringDraw drawSpring(Draw& d) {
  Particle p1, p2;
  p1.x = d.vec(3), p2.x = p1.x + d.vec(2) + Vec2(0.1, 0), p1.v = d.vec(2), p2.v = d.vec(2);
  const double l0 = d.uniform(0.1, 3), ks = d.uniform(1, 500), kd = d.uniform(0, 5);
  const Vec2 delta = p2.x - p1.x;
  const Vec2 e = delta / delta.norm();
  const SpringTerms t = referenceSpringTerms(p1, p2, l0, ks, kd);
  return {{{"ks", scalar(ks)},
           {"kd", scalar(kd)},
           {"l", scalar(delta.norm())},
           {"l0", scalar(l0)},
           {"e", e},
           {"v_rel", scalar((p2.v - p1.v).dot(e))},
           {"I", Eigen::Matrix2d::Identity()}},
          t.elastic + t.damping,
          referenceSpringJacobians(p1.x, p2.x, l0, ks, kd)};
}

// A particle in an environment, at random: the symbols of the forces' laws.
struct ParticleDraw {
  Particle p;
  Environment env;
  Bindings symbols;
};

ParticleDraw drawParticle(Draw& d) {
  ParticleDraw x;
  Particle& p = x.p;
  Environment& env = x.env;
  p.x = d.vec(2), p.v = d.vec(4), p.m = d.uniform(0.01, 5), p.temperature = d.uniform(250, 900);
  env.gravity = d.vec(10), env.airTemperature = d.uniform(250, 320);
  env.buoyancy = d.uniform(0, 0.05), env.drag = d.uniform(0, 2), env.repulsion = d.uniform(0, 2000);
  x.symbols = {{"m", scalar(p.m)},
               {"g", env.gravity},
               {"v", p.v},
               {"T", scalar(p.temperature)},
               {"T_air", scalar(env.airTemperature)},
               {"b", scalar(env.buoyancy)},
               {"k_d", scalar(env.drag)},
               {"k_r", scalar(env.repulsion)}};
  return x;
}

using Pair = std::pair<Bindings, Value>;

std::vector<Law> springLaws() {
  // The public checks' hints are read by students too.
  const std::vector<const char*> jacobianReaders = {"docs/handout.md", "starter/implicit.cpp",
                                                    "framework/include/a6/implicit.h",
                                                    "tests/task7_implicit_test.cpp"};
  return {
      {"the spring force",
       kSpringForceFormula,
       {"docs/handout.md", "starter/spring.cpp", "framework/include/a6/spring.h",
        "tests/task1_spring_test.cpp"},
       [](Draw& d) {
         const SpringDraw s = drawSpring(d);
         return Pair{s.symbols, s.force};
       }},
      {"dfdx", kDfdxFormula, jacobianReaders,
       [](Draw& d) {
         const SpringDraw s = drawSpring(d);
         return Pair{s.symbols, s.jacobians.dfdx};
       }},
      {"dfdv", kDfdvFormula, jacobianReaders,
       [](Draw& d) {
         const SpringDraw s = drawSpring(d);
         return Pair{s.symbols, s.jacobians.dfdv};
       }},
  };
}

// The texts students read the particle's laws in (the public checks' hints among them).
struct ParticleReaders {
  std::vector<const char*> forces, steps, viewer, drag;
};

ParticleReaders particleReaders() {
  ParticleReaders r;
  r.forces = {"docs/handout.md", "starter/forces.cpp", "framework/include/a6/forces.h",
              "tests/task2_forces_test.cpp"};
  r.steps = {"docs/handout.md",
             "starter/time_stepping.cpp",
             "starter/particle_system.cpp",
             "framework/include/a6/mass_spring_system.h",
             "framework/include/a6/particle_system.h",
             "tests/task3_time_stepping_test.cpp"};
  r.viewer = r.forces;
  r.viewer.insert(r.viewer.end(), {"framework/viewer/viewer.cpp", "docs/viewer.md"});
  r.drag = r.viewer;  // and the hints of the stepping checks and the scenes
  r.drag.insert(r.drag.end(), {"tests/task3_time_stepping_test.cpp", "tests/golden/manifest.json"});
  return r;
}

std::vector<Law> particleLaws() {
  const ParticleReaders readers = particleReaders();
  return {
      {"gravity", kGravityFormula, readers.forces,
       [](Draw& d) {
         const ParticleDraw x = drawParticle(d);
         return Pair{x.symbols, referenceGravity(x.p, x.env)};
       }},
      {"buoyancy", kBuoyancyFormula, readers.viewer,
       [](Draw& d) {
         const ParticleDraw x = drawParticle(d);
         return Pair{x.symbols, referenceBuoyancy(x.p, x.env)};
       }},
      {"drag", kDragFormula, readers.drag,
       [](Draw& d) {
         const ParticleDraw x = drawParticle(d);
         return Pair{x.symbols, referenceDrag(x.p, x.env)};
       }},
      {"repulsion", kRepulsionFormula, readers.forces,
       [](Draw& d) {
         ParticleDraw x = drawParticle(d);
         Contact c;
         c.depth = d.uniform(1e-3, 0.2);  // inside: outside, the force is zero by the text's words
         c.normal = d.vec(1).normalized();
         x.symbols["d"] = scalar(c.depth), x.symbols["n"] = c.normal;
         return Pair{x.symbols, referenceRepulsion(x.env.repulsion, c)};
       }},
      {"the velocity step", kVelocityStepFormula, readers.steps,
       [](Draw& d) {
         ParticleDraw x = drawParticle(d);
         x.p.f = d.vec(50);
         const double dt = d.uniform(1e-3, 0.1);
         x.symbols["f"] = x.p.f, x.symbols["dt"] = scalar(dt);
         return Pair{x.symbols, x.p.v + referenceVelocityChange(x.p, dt)};
       }},
      {"the position step", kPositionStepFormula, readers.steps,
       [](Draw& d) {
         ParticleDraw x = drawParticle(d);
         const double dt = d.uniform(1e-3, 0.1);
         x.symbols["x"] = x.p.x, x.symbols["dt"] = scalar(dt);
         return Pair{x.symbols, x.p.x + referencePositionChange(x.p, dt)};
       }},
      {"cooling",
       kCoolingFormula,
       {"docs/handout.md", "starter/particle_system.cpp", "framework/include/a6/particle_system.h"},
       [](Draw& d) {
         ParticleDraw x = drawParticle(d);
         const double rate = d.uniform(0, 3), dt = d.uniform(1e-3, 0.1);
         x.symbols["k_c"] = scalar(rate), x.symbols["dt"] = scalar(dt);
         return Pair{x.symbols, scalar(referenceCooling(x.p, x.env, rate, dt))};
       }},
  };
}

std::vector<Law> laws() {
  std::vector<Law> all = springLaws();
  for (Law& law : particleLaws()) all.push_back(std::move(law));
  return all;
}

std::string textOf(const std::string& path) {
  std::ifstream in(std::string(A6_SOURCE_DIR) + "/" + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Whether `formula` gives the law's values on 200 random inputs.
::testing::AssertionResult followsTheCode(const Law& law, const std::string& formula) {
  Draw draw;
  for (int k = 0; k < 200; ++k) {
    const auto [bindings, want] = law.draw(draw);
    const Value got = evaluateFormula(formula, bindings);
    if (got.rows() != want.rows() || got.cols() != want.cols() ||
        (got - want).norm() > 1e-9 * (1 + want.norm())) {
      return ::testing::AssertionFailure()
             << law.name << ": \"" << formula << "\" gives\n"
             << got << "\nwhere the reference's code gives\n"
             << want << "\n(grader/reference/physics.inc: change the law and its formula together)";
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(ReferenceFormulas, EachFormulaIsItsLawsCode) {
  for (const Law& law : laws()) EXPECT_TRUE(followsTheCode(law, law.formula));
}

TEST(ReferenceFormulas, EveryTextAStudentReadsHoldsTheFormula) {
  for (const Law& law : laws()) {
    for (const char* reader : law.readers) {
      const std::string text = textOf(reader);
      ASSERT_FALSE(text.empty()) << reader << " is missing or empty";
      EXPECT_NE(withoutBlanks(text).find(withoutBlanks(law.formula)), std::string::npos)
          << reader << " does not say " << law.name << " = " << law.formula
          << " (the reference's formula, grader/reference/physics.inc): a student reads the "
             "law there, so change it there too";
    }
  }
}

// The check can fail: a formula one mistake away from each law's is told apart from its code.
TEST(ReferenceFormulas, AWrongFormulaIsToldApartFromTheCode) {
  const std::vector<Law> all = laws();
  const std::map<std::string, std::string> wrong = {
      {"the spring force", "-ks (l - l0) e + kd v_rel e"},
      {"dfdx", "-ks (e eᵀ + (1 - l/l0) (I - e eᵀ))"},
      {"dfdv", "-kd (I - e eᵀ)"},
      {"gravity", "g"},
      {"buoyancy", "b (T_air - T) (0, 1)"},
      {"drag", "-k_d |v| v"},
      {"repulsion", "k_d d n"},
      {"the velocity step", "v += f dt"},
      {"the position step", "x += v"},
      {"cooling", "-k_c T dt"}};
  ASSERT_EQ(wrong.size(), all.size());
  for (const Law& law : all) {
    EXPECT_FALSE(followsTheCode(law, wrong.at(law.name)))
        << law.name << ": \"" << wrong.at(law.name) << "\" is one mistake away from the old law; "
        << "if it is the new law, give a new wrong formula here";
  }
}

TEST(ReferenceFormulas, TheNotationReadsAsTheSlideMeansIt) {
  const Bindings b = {{"v", Value(Eigen::Vector2d(3, 4))}, {"k", scalar(2)}};
  EXPECT_DOUBLE_EQ(evaluateFormula("|v|", b)(0, 0), 5);
  EXPECT_DOUBLE_EQ(evaluateFormula("v²", b)(0, 0), 25);
  EXPECT_TRUE(evaluateFormula("-k |v| v", b).isApprox(Eigen::Vector2d(-30, -40)));
  EXPECT_TRUE(evaluateFormula("k (0, 1)", b).isApprox(Eigen::Vector2d(0, 2)));
  EXPECT_DOUBLE_EQ(evaluateFormula("v·v / k", b)(0, 0), 12.5);
  EXPECT_TRUE(evaluateFormula("v vᵀ", b).isApprox((Eigen::Matrix2d() << 9, 12, 12, 16).finished()));
  EXPECT_THROW(evaluateFormula("k w", b), std::invalid_argument);  // w has no value
  EXPECT_THROW(evaluateFormula("(k", b), std::invalid_argument);
  EXPECT_THROW(evaluateFormula("v + k", b), std::invalid_argument);
  EXPECT_TRUE(evaluateFormula("v += k v", b).isApprox(Eigen::Vector2d(9, 12)));
}

}  // namespace
}  // namespace a6::test
