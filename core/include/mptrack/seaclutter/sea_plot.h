// One plot of the sea-clutter detection chain: a cluster of CFAR detections
// reduced to its amplitude-weighted centroid (seed 003 Sec. III-A step 4).
#pragma once

#include <cstddef>
#include <cstdint>

namespace mptrack::seaclutter {

struct SeaPlot {
  float range_bin = 0.0f;       ///< centroid range [bins]
  float doppler_bin = 0.0f;     ///< centroid Doppler [bins, fftshifted, zero Doppler = D/2]
  float range_m = 0.0f;         ///< range_bin * range_bin_m [m]
  float doppler_hz = 0.0f;      ///< (doppler_bin - D/2) * PRF / D [Hz]
  float range_rate_mps = 0.0f;  ///< -doppler_hz * lambda / 2 [m/s] (seed 003 eq. (4))
  float amplitude = 0.0f;       ///< sqrt(peak power / CFAR noise at the peak) [-]
  float peak_power = 0.0f;      ///< largest map power in the cluster
  std::uint16_t peak_range = 0;    ///< cell of that peak
  std::uint16_t peak_doppler = 0;
  std::uint16_t cells = 0;         ///< detections in the cluster (saturates at 65535)
  std::uint16_t patch_range_start = 0;  ///< first range bin of the patch
  std::uint16_t patch_index = 0;        ///< index of the plot's patch in the scan's patch list
};

}  // namespace mptrack::seaclutter
