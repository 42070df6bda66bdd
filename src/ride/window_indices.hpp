// EN 12299's indices from a weighted acceleration history: the RMS of consecutive 5 s windows,
// their 95th percentile per 5-minute zone, and the running RMS Cc(t).
#pragma once

#include <Eigen/Core>
#include <string>

namespace railmodal::ride {

/// √(mean of squares) of each complete window of `samples` samples, in order.
Eigen::VectorXd window_rms(const Eigen::VectorXd& values, Eigen::Index samples);

/// The 95th percentile of `values` (not empty): linear interpolation between order
/// statistics at rank 0.95·(n − 1) (Hyndman & Fan's definition 7, numpy's default).
double percentile95(const Eigen::VectorXd& values);

/// EN 12299's P95: per zone of `zone` consecutive windows (60 five-second windows: five
/// minutes), the 95th percentile of their RMS values; the largest over the complete zones,
/// or over all windows when there are fewer than a zone (then *note says so).
double zone_p95(const Eigen::VectorXd& window_values, Eigen::Index zone, std::string* note);

/// The P95 of each complete zone in order (zone_p95 is their largest); one value, over all
/// windows, when there are fewer than a zone. What N_MV combines zone by zone.
Eigen::VectorXd zone_p95s(const Eigen::VectorXd& window_values, Eigen::Index zone);

/// N_MV of one floor point from its axes' zone P95s (zone_p95s of one run, so of equal length;
/// null: the axis has no output and counts as zero): EN 12299 combines the axes' P95 of the
/// same zone, en12299_nmv, and the point's figure is the largest over the zones.
double zone_nmv(const Eigen::VectorXd* longitudinal, const Eigen::VectorXd* lateral, const Eigen::VectorXd* vertical);

/// Cc(t) = √((1/T)∫_{t−T}^{t} a_w² dτ) at every sample, T = `samples` samples; over the
/// samples so far while t < T.
Eigen::VectorXd running_rms(const Eigen::VectorXd& values, Eigen::Index samples);
/// The same into *out (resized; one already of the size is reused), which must not be `values`.
void running_rms(const Eigen::VectorXd& values, Eigen::Index samples, Eigen::VectorXd* out);

}  // namespace railmodal::ride
