// Registration entry points of the benchmark groups (called from main()).
#pragma once

namespace mptrack::bench {

/// fft/ours/<N>, fft/fftw/<N> at the front-end sizes.
void register_fft_benchmarks();
/// frontend/seed004, frontend/large: full frame time.
void register_frontend_benchmarks();
void register_cfar_benchmarks();
/// s2/<tracker>/<scalar> (seed 000 S2, all 340 scans) and
/// grid/<tracker>/<scalar>/T<t>/M<m>/C<c> (steady-state per-scan latency).
/// quick: a reduced grid.
void register_tracker_benchmarks(bool quick);

}  // namespace mptrack::bench
