// The book's permissible dynamic deflections (springs digest §5, p. 14): which elements and
// stages each rule limits, and by how much.
#include "study/permissible_deflection.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "response/friction_damping.hpp"
#include "shortest_text.hpp"

namespace railmodal {

const char* to_string(DeflectionRule::Book book) {
  switch (book) {
    case DeflectionRule::Book::none: return "none";
    case DeflectionRule::Book::korotkevich: return "korotkevich";
    case DeflectionRule::Book::lehner: return "lehner";
  }
  return "?";
}

const char* to_string(DeflectionRule::Service service) {
  return service == DeflectionRule::Service::freight ? "freight" : "passenger";
}

std::string to_string(const DeflectionRule& rule) {
  if (!rule.active()) return "none";
  std::string s = std::string(to_string(rule.book)) + " " + to_string(rule.service);
  for (const auto& [name, limit] : rule.element_limits) {
    s += "; " + name + " = " + (std::isfinite(limit) ? shortest_text(limit) : std::string()) + " m";  // exact
  }
  return s;
}

std::optional<DeflectionRule::Book> deflection_book_from_string(const std::string& word) {
  using Book = DeflectionRule::Book;
  for (Book b : {Book::none, Book::korotkevich, Book::lehner})
    if (word == to_string(b)) return b;
  return std::nullopt;
}

std::optional<DeflectionRule::Service> deflection_service_from_string(const std::string& word) {
  using Service = DeflectionRule::Service;
  for (Service s : {Service::passenger, Service::freight})
    if (word == to_string(s)) return s;
  return std::nullopt;
}

namespace study {
namespace {

std::string millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g mm", metres * 1000.0);
  return text;
}

// Static deflection of one stage under the element's static load: f_st = P/(n·c), or the
// progressive spring's own curve at its share of the load.
double static_deflection(const SpringStage& stage, double element_load) {
  const double per_spring = std::abs(element_load) / stage.count;
  if (stage.curve) return stage.curve->deflection_at(per_spring);
  return per_spring / stage.stiffness;
}

// The book names springs by kind; vehicle files may write "Coil" or "ELLIPTIC".
std::string lower_case(std::string word) {
  for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return word;
}

// Whether another stage of the element has leaf friction: friction acts inside that stage, so
// its force passes through this one, which then deflects by the force over its own stiffness
// (its share of the stretch would leave the friction force out).
bool friction_elsewhere(const Element& e, size_t stage) {
  for (size_t s = 0; s < e.vertical_stages.size(); ++s)
    if (s != stage && e.vertical_stages[s].relative_friction > 0.0) return true;
  return false;
}

// Every element a study limit names must exist (listing those with vertical springs if not).
void check_named_elements(const DeflectionRule& rule, const Vehicle& v) {
  for (const auto& [name, limit] : rule.element_limits) {
    bool found = false;
    for (const Element& e : v.elements) found = found || e.name == name;
    if (!found) {
      std::string known;
      for (const Element& e : v.elements)
        if (!e.vertical_stages.empty()) known += (known.empty() ? "" : ", ") + e.name;
      throw std::invalid_argument("permissible dynamic deflection: no element '" + name +
                                  "' with vertical springs in vehicle '" + v.name + "' (" + known + ")");
    }
  }
}

// A limit of 0 (a stage with no static load, so 0.2 f_st = 0) checks nothing meaningful.
void add_limit(const PermissibleDeflection& limit, std::vector<PermissibleDeflection>* out) {
  if (limit.permissible > 0.0) out->push_back(limit);
}

// The book's limits of the stages of element k, whose series stiffness is k_element.
void add_stage_limits(const DeflectionRule& rule, const LinearSystem& system, size_t k, double k_element,
                      std::vector<PermissibleDeflection>* out) {
  const Element& e = system.vehicle.elements[k];
  const bool passenger = rule.service == DeflectionRule::Service::passenger;
  const int element = static_cast<int>(k);
  for (size_t s = 0; s < e.vertical_stages.size(); ++s) {
    const SpringStage& stage = e.vertical_stages[s];
    const std::string kind = lower_case(stage.kind);
    // In series every stage carries the element's force: a stage deflects k_element/k_stage
    // of the element's stretch.
    const double share = k_element / (stage.stiffness * stage.count);
    const double by_force = friction_elsewhere(e, s) ? stage.stiffness * stage.count : 0.0;
    // A friction stage in series with elastic ones deflects share × (X − hold): it holds while
    // the others take the force across its band (the series model of the simulation and of the
    // criterion, response/friction_damping.hpp).
    const double hold = stage.relative_friction > 0.0 ? response::leaf_hold_stretch(system, k) : 0.0;
    const auto limit = [&](double permissible, const std::string& basis) {
      add_limit({element, static_cast<int>(s), permissible, share, basis, by_force, hold}, out);
    };
    if (rule.book == DeflectionRule::Book::korotkevich) {
      // Korotkevich (1935), p. 97: elliptic springs of passenger cars.
      if (passenger && kind == "elliptic") limit(0.030, "Korotkevich: elliptic springs of passenger cars 30 mm");
    } else if (rule.book == DeflectionRule::Book::lehner) {
      // Lehner, pp. 150–153: by spring kind; leaf springs only for freight cars.
      const double f_st = static_deflection(stage, system.element_loads[k]);
      if (kind == "coil")
        limit(0.030, "Lehner: coil springs 30 mm");
      else if (kind == "elliptic")
        limit(0.2 * f_st, "Lehner: elliptic springs 0.2 f_st = 0.2 × " + millimetres(f_st));
      else if (kind == "leaf" && !passenger)
        limit(0.4 * f_st, "Lehner: freight leaf springs 0.4 f_st = 0.4 × " + millimetres(f_st));
    }
  }
}

}  // namespace

std::vector<PermissibleDeflection> permissible_deflections(const DeflectionRule& rule, const LinearSystem& system) {
  const Vehicle& v = system.vehicle;
  check_named_elements(rule, v);
  const bool passenger = rule.service == DeflectionRule::Service::passenger;
  // Korotkevich's axle-box limits are for cars without bogies: every spring stands on the track.
  bool bogieless = true;
  for (const Element& e : v.elements) bogieless = bogieless && (e.lower.empty() || e.vertical_stages.empty());
  std::vector<PermissibleDeflection> out;
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const Element& e = v.elements[k];
    const double k_element = series_stiffness(e.vertical_stages);
    if (!(k_element > 0.0)) continue;
    const int element = static_cast<int>(k);
    bool overridden = false;
    for (const auto& [name, limit] : rule.element_limits)
      if (name == e.name) {
        add_limit({element, -1, limit, 1.0, "study: " + millimetres(limit)}, &out);
        overridden = true;
      }
    if (overridden) continue;
    add_stage_limits(rule, system, k, k_element, &out);
    // Korotkevich: the axle-box springs as a whole, of 2- and 3-axle passenger cars and of
    // bogie-less freight cars.
    if (rule.book == DeflectionRule::Book::korotkevich && bogieless && e.lower.empty())
      add_limit({element, -1, passenger ? 0.040 : 0.025, 1.0,
                 passenger ? "Korotkevich: axle-box springs of 2- and 3-axle passenger cars 40 mm"
                           : "Korotkevich: axle-box springs of bogie-less freight cars 25 mm"},
                &out);
  }
  return out;
}

}  // namespace study
}  // namespace railmodal
