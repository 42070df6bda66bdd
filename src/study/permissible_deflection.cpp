// The book's permissible dynamic deflections (springs digest §5, p. 14): which elements and
// stages each rule limits, and by how much.
#include "study/permissible_deflection.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

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

}  // namespace

std::vector<PermissibleDeflection> permissible_deflections(const DeflectionRule& rule, const LinearSystem& system) {
  const Vehicle& v = system.vehicle;
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
  const bool passenger = rule.service == DeflectionRule::Service::passenger;
  std::vector<PermissibleDeflection> out;
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const Element& e = v.elements[k];
    const double k_element = series_stiffness(e.vertical_stages);
    if (!(k_element > 0.0)) continue;
    const int element = static_cast<int>(k);
    bool overridden = false;
    for (const auto& [name, limit] : rule.element_limits)
      if (name == e.name) {
        out.push_back({element, -1, limit, 1.0, "study: " + millimetres(limit)});
        overridden = true;
      }
    if (overridden) continue;
    const bool on_track = e.lower.empty();
    if (rule.book == DeflectionRule::Book::korotkevich) {
      // Korotkevich (1935), p. 97: the axle-box springs as a whole, elliptic springs by stage.
      if (on_track)
        out.push_back({element, -1, passenger ? 0.040 : 0.025, 1.0,
                       passenger ? "Korotkevich: axle-box springs of passenger cars 40 mm"
                                 : "Korotkevich: axle-box springs of bogie-less freight cars 25 mm"});
      for (size_t s = 0; s < e.vertical_stages.size(); ++s)
        if (passenger && e.vertical_stages[s].kind == "elliptic")
          out.push_back({element, static_cast<int>(s), 0.030,
                         k_element / (e.vertical_stages[s].stiffness * e.vertical_stages[s].count),
                         "Korotkevich: elliptic springs of passenger cars 30 mm"});
    } else if (rule.book == DeflectionRule::Book::lehner) {
      // Lehner, pp. 150–153: by spring kind; leaf springs only for freight cars.
      for (size_t s = 0; s < e.vertical_stages.size(); ++s) {
        const SpringStage& stage = e.vertical_stages[s];
        const double share = k_element / (stage.stiffness * stage.count);
        const double f_st = static_deflection(stage, system.element_loads[k]);
        if (stage.kind == "coil") {
          out.push_back({element, static_cast<int>(s), 0.030, share, "Lehner: coil springs 30 mm"});
        } else if (stage.kind == "elliptic") {
          out.push_back({element, static_cast<int>(s), 0.2 * f_st, share,
                         "Lehner: elliptic springs 0.2 f_st = 0.2 × " + millimetres(f_st)});
        } else if (stage.kind == "leaf" && !passenger) {
          out.push_back({element, static_cast<int>(s), 0.4 * f_st, share,
                         "Lehner: freight leaf springs 0.4 f_st = 0.4 × " + millimetres(f_st)});
        }
      }
    }
  }
  return out;
}

}  // namespace study
}  // namespace railmodal
