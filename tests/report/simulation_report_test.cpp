// A scene's simulation as written: only the DOFs its [simulation] names, in the history's
// order, and their spectra taken exactly as fft-check takes them.
#include <algorithm>
#include <sstream>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// The two-axle wagon released in bounce, writing the DOFs `outputs` names (a TOML array).
Scene released_wagon(const std::string& outputs) {
  return load_scene(write_temp("release.toml", "[scene]\nname = \"release\"\nvehicle = \"" +
                                                   data_file("two_axle_freight_wagon.toml") +
                                                   "\"\ndofs = \"vertical\"\n[simulation]\nduration = \"1 s\"\n"
                                                   "time_step = \"10 ms\"\noutputs = " + outputs + R"(
[[simulation.initial]]
dof = "body.bounce"
displacement = "10 mm"
)"));
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(SimulationReport, WritesTheNamedOutputsInTheHistorysOrder) {
  const Scene scene = released_wagon(R"(["body.pitch", "body.bounce"])");
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  const TimeHistory h = simulate_scene(scene, vehicle);
  ASSERT_EQ(h.labels, (std::vector<std::string>{"body.bounce", "body.pitch"}));
  EXPECT_EQ(output_columns(h, scene), (std::vector<int>{0, 1}));
  std::ostringstream csv;
  write_time_history(csv, h, scene, vehicle, OutputFormat::csv);
  const std::string history = csv.str();
  EXPECT_EQ(first_line(history), "time_s,body.bounce,body.pitch");
  EXPECT_EQ(std::count(history.begin(), history.end(), '\n'), 1 + h.time.size());

  const OutputSpectra spectra = output_spectra(h, scene);
  EXPECT_EQ(spectra.dofs, h.labels);
  std::ostringstream spectra_csv;
  write_spectra(spectra_csv, spectra, OutputFormat::csv);
  const std::string text = spectra_csv.str();
  EXPECT_EQ(first_line(text), "frequency_hz,body.bounce,body.pitch");
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + spectra.spectra.front().amplitude.size());
}

TEST(SimulationReport, WritesOnlyTheNamedOutputs) {
  const Scene scene = released_wagon(R"(["body.pitch"])");
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  const TimeHistory h = simulate_scene(scene, vehicle);
  EXPECT_EQ(output_columns(h, scene), (std::vector<int>{1}));
  std::ostringstream csv, spectra_csv;
  write_time_history(csv, h, scene, vehicle, OutputFormat::csv);
  EXPECT_EQ(first_line(csv.str()), "time_s,body.pitch");
  write_spectra(spectra_csv, output_spectra(h, scene), OutputFormat::csv);
  EXPECT_EQ(first_line(spectra_csv.str()), "frequency_hz,body.pitch");
}

TEST(SimulationReport, SpectraAreThoseOfTheFftCheck) {
  const Scene scene = released_wagon(R"(["body.pitch", "body.bounce"])");
  const FftCheckResult check = fft_check(scene, load_vehicle(scene.vehicle_file));
  const OutputSpectra spectra = output_spectra(check.history, scene);
  ASSERT_FALSE(check.spectrum_dofs.empty());
  for (size_t k = 0; k < check.spectrum_dofs.size(); ++k) {
    const auto at = std::find(spectra.dofs.begin(), spectra.dofs.end(), check.spectrum_dofs[k]);
    ASSERT_NE(at, spectra.dofs.end()) << check.spectrum_dofs[k];
    const Spectrum& s = spectra.spectra[at - spectra.dofs.begin()];
    EXPECT_EQ(s.transform_length, 4 * s.signal_length);
    EXPECT_EQ(s.window, Window::hann);
    EXPECT_TRUE(s.amplitude == check.spectra[k].amplitude) << check.spectrum_dofs[k];
  }
}

}  // namespace
}  // namespace railmodal::test
