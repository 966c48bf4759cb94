// Mistakes named part by part: the spring force (task 1) is an elastic term plus a damping term,
// and springJacobians (task 7) gives two blocks, dfdx and dfdv. Each part has the physics' form
// and the wrong forms students write (a sign, a factor, a coefficient, a velocity, a direction);
// every combination of the parts' forms but the physics' own is a model. A combination is named
// only when it fits every informative answer and no other combination of its task fits them all
// (nameMistakes: MistakeModel::partByPart): the evidence singles out the part and how it is wrong.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"

namespace a6::grader::mistakes {
namespace {

#include "reference/physics.inc"

using harness::JacobiansResult;
using harness::SpringForceRequest;
using harness::SpringForceResult;

// A spring's geometry: d = x2 - x1, l = |d|, e = d / l, u = v2 - v1, P = e eᵀ, Q = I - e eᵀ.
struct Geometry {
  Vec2 d, e, u;
  double l = 0;
  Mat2 P, Q;
};

std::optional<Geometry> geometryOf(const SpringForceRequest& r) {
  Geometry g;
  g.d = r.p2.x - r.p1.x;
  g.l = g.d.norm();
  if (!(g.l >= 1e-9)) return std::nullopt;  // coincident ends: the guard's, not a term's
  g.e = g.d / g.l;
  g.u = r.p2.v - r.p1.v;
  g.P = g.e * g.e.transpose();
  g.Q = Mat2::Identity() - g.P;
  return g;
}

// One form of one part: its key (for the model's id), how it differs from the physics (for the
// student's sentence), its formula, and its value. The first form of each list is the physics'.
template <class Value>
struct Form {
  const char* key;
  const char* how;
  const char* formula;
  Value (*value)(const SpringForceRequest&, const Geometry&);
};

const std::vector<Form<Vec2>>& elasticForms() {
  static const std::vector<Form<Vec2>> forms = {
      {"", "", "-ks (l - l0) e",
       [](const SpringForceRequest& r, const Geometry&) -> Vec2 {
         return referenceSpringTerms(r.p1, r.p2, r.restLength, r.ks, r.kd).elastic;
       }},
      {"elastic_sign", "has the wrong sign", "+ks (l - l0) e",
       [](const SpringForceRequest& r, const Geometry& g) -> Vec2 {
         return r.ks * (g.l - r.restLength) * g.e;
       }},
      {"elastic_uses_d", "uses d = x2 - x1 where it needs the unit direction e = d / l",
       "-ks (l - l0) d",
       [](const SpringForceRequest& r, const Geometry& g) -> Vec2 {
         return -r.ks * (g.l - r.restLength) * g.d;
       }},
      {"elastic_no_rest_length", "leaves out the rest length", "-ks l e",
       [](const SpringForceRequest& r, const Geometry& g) -> Vec2 { return -r.ks * g.l * g.e; }},
      {"elastic_uses_kd", "uses kd where it needs ks", "-kd (l - l0) e",
       [](const SpringForceRequest& r, const Geometry& g) -> Vec2 {
         return -r.kd * (g.l - r.restLength) * g.e;
       }},
      {"elastic_missing", "is missing", "0",
       [](const SpringForceRequest&, const Geometry&) -> Vec2 { return Vec2::Zero(); }},
  };
  return forms;
}

const std::vector<Form<Vec2>>& dampingForms() {
  static const std::vector<Form<Vec2>> forms = {
      {"", "", "-kd ((v2 - v1)·e) e",
       [](const SpringForceRequest& r, const Geometry&) -> Vec2 {
         return referenceSpringTerms(r.p1, r.p2, r.restLength, r.ks, r.kd).damping;
       }},
      {"damping_sign", "has the wrong sign", "+kd ((v2 - v1)·e) e",
       [](const SpringForceRequest& r, const Geometry& g) -> Vec2 {
         return r.kd * g.u.dot(g.e) * g.e;
       }},
      {"damping_unprojected", "uses the whole relative velocity, not its part along the spring",
       "-kd (v2 - v1)",
       [](const SpringForceRequest& r, const Geometry& g) -> Vec2 { return -r.kd * g.u; }},
      {"damping_v2_only", "reads p2's velocity alone, not the relative velocity v2 - v1",
       "-kd (v2·e) e",
       [](const SpringForceRequest& r, const Geometry& g) -> Vec2 {
         return -r.kd * r.p2.v.dot(g.e) * g.e;
       }},
      {"damping_speed", "uses the speed |v2 - v1|, never negative, not the signed (v2 - v1)·e",
       "-kd |v2 - v1| e",
       [](const SpringForceRequest& r, const Geometry& g) -> Vec2 {
         return -r.kd * g.u.norm() * g.e;
       }},
      {"damping_uses_ks", "uses ks where it needs kd", "-ks ((v2 - v1)·e) e",
       [](const SpringForceRequest& r, const Geometry& g) -> Vec2 {
         return -r.ks * g.u.dot(g.e) * g.e;
       }},
      {"damping_missing", "is missing", "0",
       [](const SpringForceRequest&, const Geometry&) -> Vec2 { return Vec2::Zero(); }},
  };
  return forms;
}

const std::vector<Form<Mat2>>& dfdxForms() {
  static const std::vector<Form<Mat2>> forms = {
      {"", "", kDfdxFormula,
       [](const SpringForceRequest& r, const Geometry&) -> Mat2 {
         return referenceSpringJacobians(r.p1.x, r.p2.x, r.restLength, r.ks, r.kd).dfdx;
       }},
      {"dfdx_sign", "has the wrong sign", "+ks (e eᵀ + (1 - l0/l) (I - e eᵀ))",
       [](const SpringForceRequest& r, const Geometry& g) -> Mat2 {
         return r.ks * (g.P + (1 - r.restLength / g.l) * g.Q);
       }},
      {"dfdx_no_across", "leaves out the across-the-spring term -ks (1 - l0/l) (I - e eᵀ)",
       "-ks e eᵀ",
       [](const SpringForceRequest& r, const Geometry& g) -> Mat2 { return -r.ks * g.P; }},
      {"dfdx_isotropic", "uses the across-the-spring stiffness (1 - l0/l) along the spring too",
       "-ks (1 - l0/l) I",
       [](const SpringForceRequest& r, const Geometry& g) -> Mat2 {
         return -r.ks * (1 - r.restLength / g.l) * Mat2::Identity();
       }},
      {"dfdx_ratio_inverted", "uses l/l0 where it needs l0/l", "-ks (e eᵀ + (1 - l/l0) (I - e eᵀ))",
       [](const SpringForceRequest& r, const Geometry& g) -> Mat2 {
         return -r.ks * (g.P + (1 - g.l / r.restLength) * g.Q);
       }},
      {"dfdx_uses_kd", "uses kd where it needs ks", "-kd (e eᵀ + (1 - l0/l) (I - e eᵀ))",
       [](const SpringForceRequest& r, const Geometry& g) -> Mat2 {
         return -r.kd * (g.P + (1 - r.restLength / g.l) * g.Q);
       }},
      {"dfdx_missing", "is missing", "0",
       [](const SpringForceRequest&, const Geometry&) -> Mat2 { return Mat2::Zero(); }},
  };
  return forms;
}

const std::vector<Form<Mat2>>& dfdvForms() {
  static const std::vector<Form<Mat2>> forms = {
      {"", "", kDfdvFormula,
       [](const SpringForceRequest& r, const Geometry&) -> Mat2 {
         return referenceSpringJacobians(r.p1.x, r.p2.x, r.restLength, r.ks, r.kd).dfdv;
       }},
      {"dfdv_sign", "has the wrong sign", "+kd e eᵀ",
       [](const SpringForceRequest& r, const Geometry& g) -> Mat2 { return r.kd * g.P; }},
      {"dfdv_no_outer_product", "leaves out the outer product e eᵀ", "-kd I",
       [](const SpringForceRequest& r, const Geometry&) -> Mat2 {
         return -r.kd * Mat2::Identity();
       }},
      {"dfdv_uses_ks", "uses ks where it needs kd", "-ks e eᵀ",
       [](const SpringForceRequest& r, const Geometry& g) -> Mat2 { return -r.ks * g.P; }},
      {"dfdv_missing", "is missing", "0",
       [](const SpringForceRequest&, const Geometry&) -> Mat2 { return Mat2::Zero(); }},
  };
  return forms;
}

// The ids the catalogue gave these combinations before they were named part by part (their
// wrong versions' EXPECT files name them).
std::string knownAs(const std::string& id) {
  if (id == "t1_elastic_sign") return "t1_wrong_sign";
  if (id == "t1_damping_unprojected") return "t1_damping_full_relative_velocity";
  if (id == "t1_damping_v2_only") return "t1_damping_uses_v2_only";
  if (id == "t7_dfdx_sign") return "t7_jacobian_wrong_sign";
  if (id == "t7_dfdx_isotropic") return "t7_missing_outer_product";
  if (id == "t7_dfdv_missing") return "t7_no_damping_jacobian";
  return id;
}

// The sentence for one wrong part: "<part> <how>: yours is <formula>, the physics gives <...>".
template <class Value>
std::string partSentence(const char* part, const Form<Value>& yours, const Form<Value>& physics) {
  return std::string(part) + " " + yours.how + ": yours is " + yours.formula +
         ", the physics gives " + physics.formula;
}

// The model of a combination (i, j) of two parts' forms (not both the physics'), without its judge:
// its id (knownAs) and its sentence.
template <class A, class B>
MistakeModel describe(int task, const std::string& whose, const char* first,
                      const std::vector<Form<A>>& as, std::size_t i, const char* second,
                      const std::vector<Form<B>>& bs, std::size_t j) {
  std::string id = "t" + std::to_string(task) + "_";
  std::string text = "Your " + whose + " ";
  if (i != 0) {
    id += as[i].key;
    text += partSentence(first, as[i], as[0]);
  }
  if (i != 0 && j != 0) id += "_and_", text += "; its ";
  if (j != 0) {
    id += bs[j].key;
    text += partSentence(second, bs[j], bs[0]);
  }
  if (i == 0) text += std::string(" (its ") + first + " is right)";
  if (j == 0) text += std::string(" (its ") + second + " is right)";
  MistakeModel m{knownAs(id), task, text + ".", nullptr};
  m.partByPart = true;
  return m;
}

// Task 1's model of elastic form i and damping form j, judged on every force request.
MistakeModel forceModel(std::size_t i, std::size_t j) {
  MistakeModel m = describe(1, "spring force's", "elastic term", elasticForms(), i, "damping term",
                            dampingForms(), j);
  m.judge = [i, j](const Transcript& t) {
    std::vector<Likeness> out;
    const auto zero = [](const SpringForceResult& a) { return a.force == Vec2::Zero(); };
    if (allZero<harness::SpringForceRequest>(t, zero)) return out;
    for (const auto& x : t.of<harness::SpringForceRequest>()) {
      const SpringForceRequest& r = x.request;
      const std::optional<Geometry> g = geometryOf(r);
      if (!g) continue;
      const Vec2 physics = elasticForms()[0].value(r, *g) + dampingForms()[0].value(r, *g);
      const Vec2 mistaken = elasticForms()[i].value(r, *g) + dampingForms()[j].value(r, *g);
      const double scale = r.ks * std::max(g->l, r.restLength) + r.kd * g->u.norm();
      out.push_back(likeness(x.result.force, physics, mistaken,
                             [scale](const Vec2& a, const Vec2& b) { return near(a, b, scale); }));
    }
    return out;
  };
  return m;
}

bool nearMatrix(const Mat2& a, const Mat2& b, double scale) {
  return near(Vec2(a.col(0)), Vec2(b.col(0)), scale) && near(Vec2(a.col(1)), Vec2(b.col(1)), scale);
}

// Task 7's model of dfdx form i and dfdv form j, judged on every Jacobian request.
MistakeModel jacobianModel(std::size_t i, std::size_t j) {
  MistakeModel m = describe(7, "springJacobians'", "dfdx", dfdxForms(), i, "dfdv", dfdvForms(), j);
  m.judge = [i, j](const Transcript& t) {
    std::vector<Likeness> out;
    const auto zero = [](const JacobiansResult& a) {
      return a.dfdx == Mat2::Zero() && a.dfdv == Mat2::Zero();
    };
    if (allZero<harness::JacobiansRequest>(t, zero)) return out;
    for (const auto& x : t.of<harness::JacobiansRequest>()) {
      const SpringForceRequest& r = x.request.spring;
      const std::optional<Geometry> g = geometryOf(r);
      if (!g) continue;
      const double scale = std::max(r.ks, r.kd) * (1 + std::max(g->l, r.restLength) / g->l);
      const auto same = [scale](const JacobiansResult& a, const JacobiansResult& b) {
        return nearMatrix(a.dfdx, b.dfdx, scale) && nearMatrix(a.dfdv, b.dfdv, scale);
      };
      JacobiansResult physics, mistaken;
      physics.dfdx = dfdxForms()[0].value(r, *g), physics.dfdv = dfdvForms()[0].value(r, *g);
      mistaken.dfdx = dfdxForms()[i].value(r, *g), mistaken.dfdv = dfdvForms()[j].value(r, *g);
      out.push_back(likeness(x.result, physics, mistaken, same));
    }
    return out;
  };
  return m;
}

}  // namespace

std::vector<MistakeModel> partByPartMistakes() {
  std::vector<MistakeModel> models;
  // Every combination (i, j) of forms, in order, but the physics' (0, 0) and a stub's that returns
  // zero (every part missing: each list's last), which are no mistake; nor is a stub's answers
  // that fit a form with one part missing (allZero).
  const auto add = [&models](std::size_t a, std::size_t b,
                             MistakeModel (*model)(std::size_t, std::size_t)) {
    for (std::size_t i = 0; i < a; ++i) {
      for (std::size_t j = 0; j < b; ++j) {
        if ((i != 0 || j != 0) && (i != a - 1 || j != b - 1)) models.push_back(model(i, j));
      }
    }
  };
  add(elasticForms().size(), dampingForms().size(), forceModel);
  add(dfdxForms().size(), dfdvForms().size(), jacobianModel);
  return models;
}

}  // namespace a6::grader::mistakes
