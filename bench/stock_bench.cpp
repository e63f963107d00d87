// Speed and size of the machined-stock model (docs/verify.md): a G01
// raster of 0.1 mm horizontal blocks with a 6 mm ball end over a stock at
// 0.05 mm cells, swept with 1 and 2 threads; the columns evaluated per
// second; the grid's memory and the process's peak; and arcs (spirals from
// rounded ends, which take the certified search) for their own rate.
//
//   build/stock_bench            100 x 100 mm, 100,000 blocks, 4 M columns
//   build/stock_bench --quick    20 x 20 mm, 4,000 blocks (the test command's run)
//   ... --image DIR              also writes DIR/stock_raster.png and DIR/stock_arcs.png
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <numbers>
#include <string>
#include <sys/resource.h>
#include <vector>

#include "bezcam/stock/dexel_grid.hpp"
#include "bezcam/stock/stock_image.hpp"

using namespace bezcam;
using Clock = std::chrono::steady_clock;

namespace {

// CPU seconds of the whole process (all threads): on a machine shared with
// other work the wall time alone overstates what the sweep costs.
double cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

// Passes along X at y = 0.5, 1.5, ... (stepover 1 mm), alternating, cut in
// blocks of 0.1 mm at z = -1, with the 1 mm step between passes.
std::vector<Sweep> raster(double size, double z) {
  std::vector<Sweep> moves;
  const int passes = static_cast<int>(size), blocks = static_cast<int>(size * 10);
  for (int p = 0; p < passes; ++p) {
    const double y = p + 0.5;
    for (int b = 0; b < blocks; ++b) {
      const double xa = b * 0.1, xb = (b + 1) * 0.1;
      if (p % 2 == 0)
        moves.push_back(Sweep::line({xa, y, z}, {xb, y, z}));
      else
        moves.push_back(Sweep::line({size - xa, y, z}, {size - xb, y, z}));
    }
    if (p + 1 < passes) {
      const double x = p % 2 == 0 ? size : 0;
      moves.push_back(Sweep::line({x, y, z}, {x, y + 1, z}));
    }
  }
  return moves;
}

// Arcs of 90 degrees, radius 2 mm, their ends printed with 3 decimals (so
// spirals), descending a little each: a field of quarter circles.
std::vector<Sweep> arcs(double size, int n) {
  std::vector<Sweep> moves;
  const int per_row = static_cast<int>(std::sqrt(n));
  auto r3 = [](double v) { return std::round(v * 1000) / 1000; };
  for (int k = 0; k < n; ++k) {
    const double cx = 3 + (size - 6) * (k % per_row) / per_row, cy = 3 + (size - 6) * (k / per_row) / per_row;
    const double a0 = 0.3 * k;
    const Vec3 c{cx, cy, 0};
    const Vec3 f{r3(cx + 2 * std::cos(a0)), r3(cy + 2 * std::sin(a0)), -0.5};
    const Vec3 t{r3(cx + 2 * std::cos(a0 + std::numbers::pi / 2)), r3(cy + 2 * std::sin(a0 + std::numbers::pi / 2)),
                 -0.8};
    moves.push_back(Sweep::arc(Arc{f, t, c, true, Plane::xy}));
  }
  return moves;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string image_dir;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else if (std::strcmp(argv[i], "--image") == 0 && i + 1 < argc)
      image_dir = argv[++i];
  }
  const double size = quick ? 20 : 100, cell = 0.05;
  const ToolShape ball = ToolShape::ball(6);
  const std::vector<Sweep> moves = raster(size, -1);
  std::printf("bezcam stock: %s raster of %zu G01 blocks (0.1 mm, horizontal, stepover 1 mm), ball D6, cell %.2f mm\n",
              quick ? "20 x 20 mm" : "100 x 100 mm", moves.size(), cell);
  std::string first_hash;
  for (unsigned threads : {1u, 2u}) {
    DexelGrid grid({0, 0, -10, size, size, 0}, cell);
    grid.set_threads(threads);
    const auto t0 = Clock::now();
    const double c0 = cpu_s();
    grid.cut(moves, ball);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count(), cpu = cpu_s() - c0;
    std::printf(
        "  %u thread%s: %7.3f s (cpu %7.3f s)  %6.1f M columns/s  (%zu x %zu = %.2f M columns, grid %.1f MiB, "
        "process peak %.1f MiB)  removed %.3f mm3  hash %s\n",
        threads, threads == 1 ? " " : "s", s, cpu, static_cast<double>(grid.stats().columns) / s / 1e6, grid.nx(),
        grid.ny(), static_cast<double>(grid.nx() * grid.ny()) / 1e6, grid.memory_bytes() / 1048576.0, peak_rss_mib(),
        grid.removed_volume(), grid.hash_hex().c_str());
    if (!image_dir.empty() && threads == 1) write_stock_png(grid, image_dir + "/stock_raster.png");
    if (first_hash.empty())
      first_hash = grid.hash_hex();
    else if (first_hash != grid.hash_hex()) {
      std::printf("  the floors differ between thread counts\n");
      return 1;
    }
  }
  {
    // The same raster one move at a time, as the simulated controller sweeps.
    DexelGrid grid({0, 0, -10, size, size, 0}, cell);
    grid.set_threads(1);
    const auto t0 = Clock::now();
    const double c0 = cpu_s();
    for (const Sweep& m : moves) grid.cut(m, ball);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count(), cpu = cpu_s() - c0;
    std::printf("  one move at a time, 1 thread: %7.3f s (cpu %7.3f s)  hash %s\n", s, cpu, grid.hash_hex().c_str());
    if (grid.hash_hex() != first_hash) return 1;
  }
  const std::vector<Sweep> field = arcs(size, quick ? 400 : 10000);
  std::printf("%zu G03 arcs (90 degrees, radius 2 mm, ends at 3 decimals: spirals), ball D6\n", field.size());
  for (unsigned threads : {1u, 2u}) {
    DexelGrid grid({0, 0, -10, size, size, 0}, cell);
    grid.set_threads(threads);
    const auto t0 = Clock::now();
    const double c0 = cpu_s();
    grid.cut(field, ball);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count(), cpu = cpu_s() - c0;
    const SweepStats& st = grid.stats();
    std::printf(
        "  %u thread%s: %7.3f s (cpu %7.3f s)  %6.2f M columns/s  (%.2f M searched, %.1f intervals each, %llu closed "
        "at "
        "ulp width)  hash %s\n",
        threads, threads == 1 ? " " : "s", s, cpu, static_cast<double>(st.columns) / s / 1e6,
        static_cast<double>(st.searched_columns) / 1e6,
        static_cast<double>(st.search_intervals) / std::max(1.0, static_cast<double>(st.searched_columns)),
        static_cast<unsigned long long>(st.depth_limited), grid.hash_hex().c_str());
    if (!image_dir.empty() && threads == 1) write_stock_png(grid, image_dir + "/stock_arcs.png");
  }
  std::printf("process peak %.1f MiB\n", peak_rss_mib());
  return 0;
}
