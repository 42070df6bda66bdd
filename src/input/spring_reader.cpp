#include "input/spring_reader.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "input/input_warnings.hpp"
#include "model/spring_formulas.hpp"
#include "shortest_text.hpp"

namespace railmodal::input {
namespace {

const std::vector<std::string> kCoilGeometry = {"wire_diameter", "active_coils", "shear_modulus"};
const std::vector<std::string> kLeafGeometry = {"length", "leaf_width", "leaf_thickness", "leaves",
                                                "full_length_leaves", "modulus"};
const std::vector<std::string> kEllipticGeometry = {"length", "leaf_width", "leaf_thickness",
                                                    "leaves", "rows", "modulus"};
const std::vector<std::string> kOneSpring = {
    "stiffness",           "flexibility", "static_deflection", "load_deflection", "mean_radius", "mean_diameter",
    "shackle_inclination", "free_camber", "relative_friction", "leaf_friction",   "load"};

bool any_of(const TableReader& t, const std::vector<std::string>& keys) {
  for (const auto& k : keys)
    if (t.has(k)) return true;
  return false;
}

double load_per_spring(TableReader& t, std::optional<double> element_load, int count,
                       const std::string& why) {
  if (t.has("load")) return t.positive("load", Quantity::force);
  if (element_load && *element_load > 0.0) return *element_load / count;
  t.fail(why, "needs the static load one spring carries: add load = \"5660 kgf\" to the "
              "stage or to its element");
}

// load_deflection = { deflection = ["0 mm", "70 mm", ...], load = ["0 kgf", "1820 kgf", ...] }:
// points of one spring from the unloaded state, both increasing.
LoadDeflectionCurve read_curve(TableReader& stage) {
  TableReader t = stage.table("load_deflection");
  LoadDeflectionCurve c;
  c.deflection = t.quantities("deflection", Quantity::length);
  c.load = t.quantities("load", Quantity::force);
  if (c.deflection.size() != c.load.size())
    t.fail("load", "has " + std::to_string(c.load.size()) + " points, deflection has " +
                       std::to_string(c.deflection.size()));
  if (c.deflection.size() < 2) t.fail("deflection", "needs at least two points");
  if (c.deflection[0] != 0.0 || c.load[0] != 0.0)
    t.fail("deflection", "the curve starts at the unloaded spring: first point 0 and 0");
  for (size_t i = 1; i < c.deflection.size(); ++i) {
    if (!(c.deflection[i] > c.deflection[i - 1])) t.fail("deflection", "must increase from point to point");
    if (!(c.load[i] > c.load[i - 1])) t.fail("load", "must increase from point to point (a spring that stiffens or softens, never gives way)");
  }
  t.finish();
  return c;
}

// Exactly one way of giving the stiffness: one of the keys, or the kind's geometry (returned
// as "coil geometry", "leaf geometry" or "elliptic geometry").
std::string stiffness_given_by(const TableReader& t, const std::string& kind) {
  std::vector<std::string> given;
  for (const char* k : {"stiffness", "flexibility", "static_deflection", "load_deflection"})
    if (t.has(k)) given.push_back(k);
  const bool coil = kind == "coil" && any_of(t, kCoilGeometry);
  const bool leaf = kind == "leaf" && any_of(t, kLeafGeometry);
  const bool elliptic = kind == "elliptic" && any_of(t, kEllipticGeometry);
  if (coil || leaf || elliptic) given.push_back(kind + " geometry");
  if (given.empty())  // "stifness", "flexibilty": point at it rather than say "missing"
    for (const char* key : {"stiffness", "flexibility", "static_deflection", "load_deflection"}) t.refuse_misspelling(key);
  if (given.size() != 1) {
    const std::string choices =
        "give exactly one of stiffness, flexibility, static_deflection, load_deflection" +
        std::string(kind == "coil"       ? " or the coil geometry (wire_diameter, mean_radius, active_coils, shear_modulus)"
                    : kind == "leaf"     ? " or the leaf geometry (length, leaf_width, leaf_thickness, leaves, full_length_leaves, modulus)"
                    : kind == "elliptic" ? " or the elliptic geometry (length, leaf_width, leaf_thickness, leaves, rows, modulus)"
                                         : "");
    t.fail(given.empty() ? "stiffness" : given[1], given.empty() ? "missing: " + choices
                                                                 : "conflicts with " + given[0] + ": " + choices);
  }
  return given[0];
}

// The tangent of the load-deflection curve at the load the spring carries.
double curve_stiffness(TableReader& t, std::optional<double> element_load, SpringStage* stage) {
  LoadDeflectionCurve& curve = stage->curve.emplace(read_curve(t));
  const double load = load_per_spring(t, element_load, stage->count, "load_deflection");
  if (load > curve.load.back())
    t.fail("load", "is beyond the last point of load_deflection; extend the curve");
  return curve.stiffness_at(load);
}

// A spring's positive dimension, warned when beyond a spring's scale (input_warnings.hpp).
double spring_dimension(TableReader& t, const std::string& key) {
  const double value = t.positive(key, Quantity::length);
  warn_implausible_length(t, key, value, kSpringLength);
  return value;
}

double coil_stiffness(TableReader& t) {
  const double d = spring_dimension(t, "wire_diameter");
  double r = 0.0;
  if (t.has("mean_radius") == t.has("mean_diameter"))
    t.fail("mean_radius", "give exactly one of mean_radius and mean_diameter");
  r = t.has("mean_radius") ? spring_dimension(t, "mean_radius")
                           : spring_dimension(t, "mean_diameter") / 2.0;
  const double n = t.positive("active_coils", Quantity::dimensionless);
  const double G = t.positive("shear_modulus", Quantity::modulus);
  return model::coil_spring_stiffness(d, r, n, G);  // eq. (4)
}

// The leaf spring's geometry into *g, and its stiffness: at the carried load where inclined
// shackles make it depend on the load.
double leaf_stiffness(TableReader& t, std::optional<double> element_load, int count, model::LeafSpringGeometry* g) {
  g->length = spring_dimension(t, "length");
  g->leaf_width = spring_dimension(t, "leaf_width");
  g->leaf_thickness = spring_dimension(t, "leaf_thickness");
  g->leaves = t.count("leaves", 1);
  g->full_length_leaves = t.count("full_length_leaves", 1);
  if (g->full_length_leaves > g->leaves) t.fail("full_length_leaves", "cannot exceed leaves");
  g->modulus = t.positive("modulus", Quantity::modulus);
  g->shackle_inclination = t.optional_positive("shackle_inclination", Quantity::angle, true).value_or(0.0);
  if (g->shackle_inclination >= 1.5707963267948966)
    t.fail("shackle_inclination", "must be below 90 degrees (write \"33.4 deg\")");
  g->free_camber = t.optional_positive("free_camber", Quantity::length, true).value_or(0.0);
  if (g->shackle_inclination > 0.0 && !t.has("free_camber"))
    t.fail("free_camber", "missing: inclined shackles need the free (factory) camber, eq. (92a)");
  const double load = g->shackle_inclination > 0.0 ? load_per_spring(t, element_load, count, "shackle_inclination")
                                                   : 1.0;  // linear: any load gives the same stiffness
  return model::leaf_spring_stiffness(*g, load);  // eqs. (26), (92a), (93)
}

double elliptic_stiffness(TableReader& t) {
  return model::elliptic_spring_stiffness(
      spring_dimension(t, "length"), spring_dimension(t, "leaf_width"),
      spring_dimension(t, "leaf_thickness"), t.count("leaves", 1), t.count("rows", 1),
      t.positive("modulus", Quantity::modulus));
}

// Leaf friction: φ directly, or Marié's eq. (34) from the leaf-on-leaf coefficient ψ.
void read_leaf_friction(TableReader& t, const std::optional<model::LeafSpringGeometry>& leaf, SpringStage* stage) {
  if (t.has("relative_friction") && t.has("leaf_friction"))
    t.fail("leaf_friction", "conflicts with relative_friction: give one of them");
  if (t.has("relative_friction")) {
    stage->relative_friction = t.positive("relative_friction", Quantity::dimensionless, true);
    if (!(stage->relative_friction < 1.0))
      t.fail("relative_friction", "must be below 1 (the book's φ is 0.02 … 0.15)");
  } else if (t.has("leaf_friction")) {
    if (!leaf) t.fail("leaf_friction", "needs the leaf geometry (Marié's eq. (34)); or give relative_friction");
    const double psi = t.positive("leaf_friction", Quantity::dimensionless, true);
    stage->relative_friction = model::leaf_spring_relative_friction(*leaf, psi);
    if (!(stage->relative_friction < 1.0))
      t.fail("leaf_friction",
             "gives a relative friction φ of " + shortest_text(stage->relative_friction, 4) + ", not below 1");
  }
}

// The first key of `t` that describes one spring (its stiffness, geometry, load or friction),
// which a stage of springs in parallel takes from the springs it lists instead; "" for none.
std::string one_spring_key(const TableReader& t) {
  for (const auto* keys : {&kCoilGeometry, &kLeafGeometry, &kEllipticGeometry, &kOneSpring})
    for (const auto& k : *keys)
      if (t.has(k)) return k;
  return "";
}

// One spring of a parallel set. The set's springs deflect together and share its load by
// their stiffness, so the element's load does not say what one of them carries (a spring
// given by static deflection needs its own `load`), and what is not linear in the one
// deflection they share (a progressive curve, leaf friction) is refused.
SpringStage read_parallel_spring(TableReader& t) {
  if (t.has("parallel")) t.fail("parallel", "springs in parallel are listed once, not nested");
  for (const char* key : {"load_deflection", "relative_friction", "leaf_friction"})
    if (t.has(key))
      t.fail(key,
             "a spring in parallel with others is taken as linear and without friction; give it as a "
             "stage of its own (in series) or give its stiffness");
  for (const char* key : {"static_deflection", "shackle_inclination"})
    if (t.has(key) && !t.has("load"))
      t.fail(key,
             "needs the load this spring carries (`load`): springs in parallel share the element's load "
             "by their stiffness, so the element's load does not say");
  return read_spring_stage(t, std::nullopt);
}

// "coil", or "coil + leaf" for a mixed set: each kind once, in the order given.
std::string join_kinds(const std::vector<std::string>& kinds) {
  std::string joined;
  for (size_t i = 0; i < kinds.size(); ++i)
    if (std::find(kinds.begin(), kinds.begin() + i, kinds[i]) == kinds.begin() + i)
      joined += (joined.empty() ? "" : " + ") + kinds[i];
  return joined;
}

// A stage of different springs side by side (nested coil springs): `parallel = [{...}, ...]`,
// c = Σ cᵢ (springs digest eq. (25)), with the stage's own `kind` and `count` (sets of them).
SpringStage read_parallel_stage(TableReader& t) {
  SpringStage stage;
  const std::string misplaced = one_spring_key(t);
  if (!misplaced.empty())
    t.fail(misplaced,
           "conflicts with parallel: a stage of springs in parallel takes its stiffness from the "
           "springs it lists; move this key into one of them");
  std::vector<TableReader> springs = t.tables("parallel");
  if (springs.size() < 2)
    t.fail("parallel", "lists " + std::to_string(springs.size()) +
                           " spring(s): springs in parallel are at least two (one spring is a stage of its own)");
  std::vector<std::string> kinds;
  for (auto& s : springs) {
    const SpringStage one = read_parallel_spring(s);
    stage.stiffness += one.stiffness * one.count;
    kinds.push_back(one.kind);
  }
  stage.kind = t.optional_string("kind").value_or(join_kinds(kinds));
  stage.count = t.optional_count("count", 1).value_or(1);
  t.finish();
  return stage;
}

}  // namespace

SpringStage read_spring_stage(TableReader& t, std::optional<double> element_load) {
  if (t.has("parallel")) return read_parallel_stage(t);
  SpringStage stage;
  stage.kind = t.optional_string("kind").value_or("spring");
  stage.count = t.optional_count("count", 1).value_or(1);
  const std::string way = stiffness_given_by(t, stage.kind);
  std::optional<model::LeafSpringGeometry> leaf_geometry;
  if (way == "stiffness") {
    stage.stiffness = t.positive("stiffness", Quantity::stiffness);
  } else if (way == "flexibility") {
    stage.stiffness = 1.0 / t.positive("flexibility", Quantity::flexibility);
  } else if (way == "static_deflection") {
    const double f = spring_dimension(t, "static_deflection");
    stage.stiffness = load_per_spring(t, element_load, stage.count, "static_deflection") / f;
  } else if (way == "load_deflection") {
    stage.stiffness = curve_stiffness(t, element_load, &stage);
  } else if (way == "coil geometry") {
    stage.stiffness = coil_stiffness(t);
  } else if (way == "leaf geometry") {
    stage.stiffness = leaf_stiffness(t, element_load, stage.count, &leaf_geometry.emplace());
  } else {
    stage.stiffness = elliptic_stiffness(t);
  }
  read_leaf_friction(t, leaf_geometry, &stage);
  if (t.has("load") && way != "static_deflection" && way != "load_deflection" &&
      !(leaf_geometry && t.has("shackle_inclination")))
    t.positive("load", Quantity::force);  // documented carried load; accepted, not needed
  t.finish();
  return stage;
}

std::vector<SpringStage> read_spring_stages(TableReader& parent, const std::string& key,
                                            std::optional<double> element_load) {
  std::vector<SpringStage> stages;
  if (!parent.has(key)) return stages;
  for (auto& t : parent.tables(key)) stages.push_back(read_spring_stage(t, element_load));
  return stages;
}

std::vector<SpringStage> read_longitudinal_stages(TableReader& parent, const std::string& key,
                                                  std::optional<double> element_load) {
  std::vector<SpringStage> stages;
  if (!parent.has(key)) return stages;
  for (auto& t : parent.tables(key)) {
    for (const char* friction : {"relative_friction", "leaf_friction"})
      if (t.has(friction))
        t.fail(friction,
               "leaf friction is taken from vertical stages only; a longitudinal stage is a linear spring: "
               "give its stiffness alone");
    stages.push_back(read_spring_stage(t, element_load));
  }
  return stages;
}

Eigen::Vector3d read_rotational_stiffness(TableReader& parent) {
  Eigen::Vector3d k = Eigen::Vector3d::Zero();
  if (!parent.has("rotational")) return k;
  TableReader t = parent.table("rotational");
  const char* names[] = {"roll", "pitch", "yaw"};
  for (int r = 0; r < 3; ++r)
    k(r) = t.optional_positive(names[r], Quantity::rotational_stiffness, true).value_or(0.0);
  t.finish();
  return k;
}

std::vector<SeriesDamper> read_series_dampers(TableReader& parent) {
  std::vector<SeriesDamper> dampers;
  if (!parent.has("series_dampers")) return dampers;
  for (auto& t : parent.tables("series_dampers")) {
    SeriesDamper d;
    const std::string direction = t.string("direction");
    if (direction == "longitudinal")
      d.direction = Motion::longitudinal;
    else if (direction == "lateral")
      d.direction = Motion::lateral;
    else if (direction == "vertical")
      d.direction = Motion::bounce;
    else
      t.fail("direction", "unknown direction '" + direction + "' (longitudinal, lateral or vertical)");
    d.damping = t.positive("damping", Quantity::damping);
    d.stiffness = t.positive("stiffness", Quantity::stiffness);
    t.finish();
    dampers.push_back(d);
  }
  return dampers;
}

SwingHanger read_hanger(TableReader& parent) {
  TableReader t = parent.table("hanger");
  SwingHanger h;
  h.length = t.positive("length", Quantity::length);
  warn_implausible_length(t, "length", h.length, kHangerLength);  // a bare "734": 734 m, a 54 s sway
  h.inclination = t.optional_quantity("inclination", Quantity::angle).value_or(0.0);
  if (!(std::abs(h.inclination) < 1.3962634015954636))  // 80°: beyond, cos α ≈ 0
    t.fail("inclination", "must be within ±80 degrees; write units, e.g. \"14 deg\"");
  t.finish();
  return h;
}

}  // namespace railmodal::input
