// Design studies: a study file evaluated and ranked, and variants built in Python (Vehicle
// objects) evaluated in one batched call on the study's threads without any TOML
// (docs/python.md, "Studies").
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis_values.hpp"
#include "bindings.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/study.hpp"

namespace railmodal::python {
namespace {

std::string parameters_text(const std::vector<StudyParameter>& parameters) {
  std::string out;
  for (const StudyParameter& p : parameters) out += (out.empty() ? "" : "; ") + p.first + " = " + p.second;
  return out;
}

// The results of a study's variants, in index order.
struct VariantResults {
  std::vector<VariantResult> results;
  AnalysisSummary summary;
};

py::object metric_or_none(const VariantResult& r, const std::string& metric) {
  return optional_value(r.ok() ? metric_value(r, metric) : std::nullopt);
}

// One row per variant: the figures every variant has, metrics that may be missing as None.
py::dict variant_record(const VariantResult& r) {
  return py::dict(py::arg("index") = r.index, py::arg("name") = r.name,
                  py::arg("parameters") = parameters_text(r.parameters), py::arg("ok") = r.ok(),
                  py::arg("failure") = r.failure, py::arg("mode_count") = r.modes.size(),
                  py::arg("lowest_critical_speed_m_s") = metric_or_none(r, "lowest_critical_speed"),
                  py::arg("metacentric_height_m") = optional_value(r.metacentric_height),
                  py::arg("hunting_speed_m_s") = optional_value(r.hunting_speed),
                  py::arg("max_nmv") = optional_value(r.max_nmv), py::arg("max_nmv_partial") = r.max_nmv_partial,
                  py::arg("dynamic_deflection_ratio") =
                      r.deflections_checked ? metric_or_none(r, "dynamic_deflection_ratio") : py::none());
}

template <class Rows>
py::list per_variant(const std::vector<VariantResult>& results, const Rows& rows) {
  py::list out;
  for (const VariantResult& r : results) rows(r, out);
  return out;
}

void bind_variant_results(py::module_& m) {
  py::class_<VariantResults>(m, "VariantResults",
                             "What a study's evaluation found, one variant a row (records, modes, critical_speeds, "
                             "peaks, ride, deflections, static_deflections; metric(name) as an array)")
      .def("__len__", [](const VariantResults& r) { return r.results.size(); })
      .def(
          "records",
          [](const VariantResults& r) {
            return per_variant(r.results, [](const VariantResult& v, py::list& out) { out.append(variant_record(v)); });
          },
          "One row per variant: index, name, parameters, ok, failure, mode_count, lowest_critical_speed_m_s "
          "(m/s), metacentric_height_m (m), hunting_speed_m_s (m/s), max_nmv (dimensionless), max_nmv_partial (what a "
          "partial max_nmv covers, 'vertical only'; '' when it is over the lateral and vertical axes), "
          "dynamic_deflection_ratio (deflection / permissible, dimensionless)")
      .def(
          "modes",
          [](const VariantResults& r) {
            return per_variant(r.results, [](const VariantResult& v, py::list& out) {
              for (const VariantResult::ModeSummary& s : v.modes)
                out.append(py::dict(py::arg("index") = v.index, py::arg("variant") = v.name, py::arg("name") = s.name,
                                    py::arg("kind") = s.kind, py::arg("frequency_hz") = s.frequency_hz,
                                    py::arg("period_s") = s.period_s, py::arg("divergence_rate_per_s") = s.divergence_rate));
            });
          },
          "One row per variant and mode: index, variant, name, kind, frequency_hz (Hz), period_s (s), "
          "divergence_rate_per_s (1/s)")
      .def(
          "critical_speeds",
          [](const VariantResults& r) {
            return per_variant(r.results, [](const VariantResult& v, py::list& out) {
              for (const VariantResult::CriticalSpeedSummary& c : v.critical_speeds)
                out.append(py::dict(py::arg("index") = v.index, py::arg("variant") = v.name,
                                    py::arg("speed_m_s") = c.speed, py::arg("source_index") = c.source + 1,
                                    py::arg("source_kind") = c.source_kind, py::arg("harmonic") = c.harmonic,
                                    py::arg("mode_name") = c.mode_name, py::arg("friction_stops") = c.friction_stops));
            });
          },
          "One row per variant and critical speed, ascending: index, variant, speed_m_s (m/s), source_index (the "
          "scene's source, from 1, as compare's JSON), "
          "source_kind, harmonic, mode_name, friction_stops")
      .def(
          "peaks",
          [](const VariantResults& r) {
            return per_variant(r.results, [](const VariantResult& v, py::list& out) {
              for (const VariantResult::PeakSummary& p : v.peaks)
                out.append(py::dict(py::arg("index") = v.index, py::arg("variant") = v.name, py::arg("source_index") = p.source + 1,
                                    py::arg("output") = p.output, py::arg("quantity") = p.quantity,
                                    py::arg("amplitude") = p.amplitude, py::arg("speed_m_s") = p.speed,
                                    py::arg("unbounded") = p.unbounded));
            });
          },
          "One row per variant, source and output, the largest response over the scene's speeds: index, variant, "
          "source_index, output, quantity, amplitude (the quantity's unit: m, m/s or m/s²; rad... for a rotation), "
          "speed_m_s (m/s), unbounded")
      .def(
          "ride",
          [](const VariantResults& r) {
            return per_variant(r.results, [](const VariantResult& v, py::list& out) {
              for (const VariantResult::RideSummary& s : v.ride)
                out.append(py::dict(py::arg("index") = v.index, py::arg("variant") = v.name, py::arg("output") = s.output,
                                    py::arg("unit") = s.unit, py::arg("max_rms") = s.max_rms,
                                    py::arg("max_wz") = optional_value(s.max_wz), py::arg("unbounded") = s.unbounded));
            });
          },
          "One row per variant and ride output (scenes with a [ride]): index, variant, output, unit (the output's: "
          "m, m/s, m/s² or N), max_rms (unit, the largest over the speeds), max_wz (dimensionless), unbounded")
      .def(
          "deflections",
          [](const VariantResults& r) {
            return per_variant(r.results, [](const VariantResult& v, py::list& out) {
              for (const VariantResult::DeflectionCheck& d : v.deflections)
                out.append(py::dict(py::arg("index") = v.index, py::arg("variant") = v.name, py::arg("element") = d.element,
                                    py::arg("stage") = d.stage, py::arg("basis") = d.basis,
                                    py::arg("permissible_m") = d.permissible, py::arg("deflection_m") = d.deflection,
                                    py::arg("speed_m_s") = d.speed, py::arg("source_index") = d.source + 1,
                                    py::arg("unbounded") = d.unbounded, py::arg("kept") = d.kept()));
            });
          },
          "One row per variant and permissible-deflection check: index, variant, element, stage, basis (where the "
          "limit comes from), permissible_m and deflection_m (m), speed_m_s (m/s), source_index, unbounded, kept (the "
          "deflection within the permissible one)")
      .def(
          "static_deflections",
          [](const VariantResults& r) {
            return per_variant(r.results, [](const VariantResult& v, py::list& out) {
              for (const auto& [body, deflection] : v.static_deflections)
                out.append(py::dict(py::arg("index") = v.index, py::arg("variant") = v.name, py::arg("body") = body,
                                    py::arg("deflection_m") = deflection));
            });
          },
          "One row per variant and body")
      .def(
          "metric",
          [](const VariantResults& r, const std::string& metric) {
            if (!is_metric(metric)) throw py::value_error("'" + metric + "' is not a metric (docs/studies.md lists them)");
            return column(r.results.size(), [&](size_t i) {
              const std::optional<double> v = r.results[i].ok() ? metric_value(r.results[i], metric) : std::nullopt;
              return v ? *v : std::numeric_limits<double>::quiet_NaN();
            });
          },
          py::arg("name"), "A metric (SI, metric_unit) per variant, NaN where a variant has none or failed")
      .def_readonly("summary", &VariantResults::summary);
  m.def("metric_unit", [](const std::string& metric) { return std::string(metric_unit(metric)); }, py::arg("metric"),
        "The SI unit of a metric's values ('' for a ratio)");
}

py::dict ranking_dict(const Ranking& ranking) {
  py::list constraints, objective;
  for (const RankingConstraint& c : ranking.constraints)
    constraints.append(py::dict(py::arg("metric") = c.metric, py::arg("min") = optional_value(c.min),
                                py::arg("max") = optional_value(c.max)));
  for (const RankingCriterion& c : ranking.objective)
    objective.append(py::dict(py::arg("metric") = c.metric, py::arg("maximise") = c.maximise, py::arg("weight") = c.weight));
  return py::dict(py::arg("constraints") = constraints, py::arg("objective") = objective,
                  py::arg("weighted") = ranking.weighted);
}

void bind_comparison(py::module_& m) {
  py::class_<Comparison>(m, "Comparison", "A study's variants ranked (feasible first)")
      .def_readonly("study", &Comparison::study)
      .def_property_readonly("ranking", [](const Comparison& c) { return ranking_dict(c.ranking); })
      .def(
          "records",
          [](const Comparison& c) {
            py::list out;
            for (const RankedVariant& v : c.variants) {
              py::dict row = variant_record(v.result);
              row["rank"] = v.rank;
              row["feasible"] = v.feasible;
              std::string violations;
              for (const std::string& w : v.violations) violations += (violations.empty() ? "" : "; ") + w;
              row["violations"] = violations;
              row["objective"] = optional_value(v.objective);
              for (size_t k = 0; k < c.ranking.objective.size(); ++k)
                row[py::str(c.ranking.objective[k].metric)] = optional_value(v.criteria[k]);
              out.append(row);
            }
            return out;
          },
          "One row per variant in rank order: the variant's figures (VariantResults.records), rank, feasible, "
          "violations, objective (the ranking's value: the criterion's SI unit, or weights × SI values when "
          "weighted) and each objective criterion by its metric, in the metric's SI unit (metric_unit(name))")
      .def_property_readonly("results",
                             [](const Comparison& c) {
                               VariantResults out;
                               for (const RankedVariant& v : c.variants) out.results.push_back(v.result);
                               return out;
                             },
                             "the variants' results in rank order")
      .def_readonly("summary", &Comparison::summary);
}

void bind_study_file(py::module_& m) {
  py::class_<Study, std::shared_ptr<Study>>(m, "Study", "A design study read from its file (load_study)")
      .def_readonly("name", &Study::name)
      .def_readonly("source", &Study::source)
      .def(
          "variants",
          [](const Study& s) {
            py::list out;
            for (size_t i = 0; i < s.variants.size(); ++i)
              out.append(py::dict(py::arg("index") = i, py::arg("name") = s.variants[i].name,
                                  py::arg("parameters") = parameters_text(s.variants[i].parameters)));
            return out;
          },
          "records: index, name, parameters")
      .def_property_readonly("ranking", [](const Study& s) { return ranking_dict(s.ranking); })
      .def_property_readonly("deflection_rule", [](const Study& s) { return to_string(s.deflection_rule); })
      .def_property_readonly("files", [](const Study& s) { return study_files(s); });

  m.def(
      "load_study",
      [](const py::object& path, bool read_variants) {
        const std::string file = path_argument(path);
        std::vector<std::string> warnings;
        std::shared_ptr<Study> study;
        {
          py::gil_scoped_release release;
          study = read_variants ? std::make_shared<Study>(load_study(file, {}, &warnings))
                                : std::make_shared<Study>(load_study(file, [](int) { return false; }, &warnings));
        }
        warn_input(warnings);  // as load_vehicle's binding does: InputWarning, with the GIL held
        return study;
      },
      py::arg("path"), py::kw_only(), py::arg("read_variants") = true,
      "Reads a study file and every variant; InputError naming the study file, line, variant and key; "
      "the base vehicle file's and the scene's warnings (as written, once) as InputWarning. "
      "read_variants=False names the variants without reading them: evaluate or compare them with "
      "read_in_workers=True, which reads each on the thread that evaluates it (a large study in little memory).");
  m.def(
      "evaluate_study",
      [](const Study& study, int threads, bool read_in_workers) {
        EvaluationOptions options;
        options.threads = threads;
        options.read_in_workers = read_in_workers;
        py::gil_scoped_release release;
        VariantResults out;
        out.results = evaluate_study(study, options, &out.summary);
        return out;
      },
      py::arg("study"), py::kw_only(), py::arg("threads") = EvaluationOptions{}.threads,
      py::arg("read_in_workers") = EvaluationOptions{}.read_in_workers,
      "Evaluates every variant on `threads` threads (0: every core); a variant that cannot be evaluated is a row "
      "with its failure. read_in_workers: see load_study(read_variants=False).");
  m.def(
      "compare",
      [](const Study& study, int threads, bool read_in_workers) {
        EvaluationOptions options;
        options.threads = threads;
        options.read_in_workers = read_in_workers;
        py::gil_scoped_release release;
        return rank_variants(study, evaluate_study(study, options));
      },
      py::arg("study"), py::kw_only(), py::arg("threads") = EvaluationOptions{}.threads,
      py::arg("read_in_workers") = EvaluationOptions{}.read_in_workers,
      "Evaluates and ranks the study's variants ('railmodal compare').");
}

// The study of `vehicles` in `scene`, each a variant, without a file.
Study study_of(const Scene& scene, const std::vector<Vehicle>& vehicles, const std::vector<std::string>& names,
               const DeflectionRule& rule) {
  if (!names.empty() && names.size() != vehicles.size())
    throw py::value_error("names: " + std::to_string(names.size()) + " names for " + std::to_string(vehicles.size()) +
                          " vehicles");
  Study study;
  study.name = scene.name;
  study.deflection_rule = rule;
  for (size_t i = 0; i < vehicles.size(); ++i) {
    StudyVariant v;
    v.name = names.empty() ? (vehicles[i].name.empty() ? "variant " + std::to_string(i + 1) : vehicles[i].name) : names[i];
    v.vehicle = vehicles[i];
    v.scene = scene;
    study.variants.push_back(std::move(v));
  }
  return study;
}

void bind_batched_variants(py::module_& m) {
  m.def(
      "evaluate_variants",
      [](const Scene& scene, const std::vector<Vehicle>& vehicles, const std::vector<std::string>& names,
         const std::string& book, const std::string& service, bool hunting_speed, int threads) {
        DeflectionRule rule;
        rule.book = enum_argument(book, deflection_book_from_string, "deflection_rule", "'none', 'korotkevich', 'lehner'");
        rule.service = enum_argument(service, deflection_service_from_string, "service", "'passenger', 'freight'");
        Study study = study_of(scene, vehicles, names, rule);
        study.every_analysis = true;  // ranks nothing, returns every figure
        if (hunting_speed) study.ranking.objective.push_back({"hunting_speed", true, 1.0, {}});  // asks for the metric
        EvaluationOptions options;
        options.threads = threads;
        py::gil_scoped_release release;
        VariantResults out;
        out.results = evaluate_study(study, options, &out.summary);
        return out;
      },
      py::arg("scene"), py::arg("vehicles"), py::kw_only(), py::arg("names") = std::vector<std::string>{},
      py::arg("deflection_rule") = "none", py::arg("service") = "passenger", py::arg("hunting_speed") = false,
      py::arg("threads") = EvaluationOptions{}.threads,
      "Evaluates each Vehicle in `scene` as a study variant (modes, critical speeds, peaks, static deflections, "
      "and when asked the permissible deflections by a book's rule and the hunting speed), in one call on "
      "`threads` threads: the batched form of a study whose variants Python builds, without TOML.");
}

}  // namespace

void bind_study(py::module_& m) {
  bind_variant_results(m);
  bind_comparison(m);
  bind_study_file(m);
  bind_batched_variants(m);
}

}  // namespace railmodal::python
