#include "bezcam/stock/dexel_grid.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>
#include <variant>

#include "bezcam/error.hpp"
#include "floors.hpp"

namespace bezcam {

using namespace stock_detail;

namespace {

// Columns along one axis: ceil(extent / cell), a quotient within 1e-9 of a
// whole number counting as that number.
double columns(double extent, double cell) {
  const double q = extent / cell;
  const double r = std::round(q);
  if (std::abs(q - r) <= 1e-9 * std::max(1.0, q)) return std::max(1.0, r);
  return std::ceil(q);
}

std::string mib(double bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f MiB", bytes / (1024.0 * 1024.0));
  return b;
}

constexpr int kRowsPerChunk = 8;

struct Prepared {
  std::variant<LinePrep, ArcPrep> geom;
  long j0 = 0, j1 = -1;  // rows it may reach
};

}  // namespace

StockGridSize stock_grid_size(const StockBox& b, double cell) {
  const double v[6] = {b.x0, b.y0, b.z0, b.x1, b.y1, b.z1};
  for (double x : v)
    if (!std::isfinite(x))
      throw InputError(errc::stock_box, Place::at_setting("box"), "a stock box's bounds must be finite numbers");
  if (!(b.x1 > b.x0) || !(b.y1 > b.y0) || !(b.z1 > b.z0))
    throw InputError(errc::stock_box, Place::at_setting("box"),
                     "a stock box needs x0 < x1, y0 < y1 and z0 < z1, not " + fmt_num(b.x0) + "," + fmt_num(b.y0) +
                         "," + fmt_num(b.z0) + "," + fmt_num(b.x1) + "," + fmt_num(b.y1) + "," + fmt_num(b.z1));
  if (!std::isfinite(cell) || !(cell > 0))
    throw InputError(errc::stock_cell, Place::at_setting("cell"),
                     "a stock's cell size must be a finite number > 0, not " + fmt_num(cell));
  const double nx = columns(b.x1 - b.x0, cell), ny = columns(b.y1 - b.y0, cell);
  StockGridSize s;
  s.bytes = nx * ny * sizeof(double) + ny * sizeof(void*) + sizeof(DexelGrid);
  // Sizes that do not fit an index are refused by the memory check anyway.
  s.nx = nx < 1e15 ? static_cast<std::size_t>(nx) : 0;
  s.ny = ny < 1e15 ? static_cast<std::size_t>(ny) : 0;
  return s;
}

DexelGrid::DexelGrid(const StockBox& box, double cell, std::size_t memory_limit) : box_(box), cell_(cell) {
  const StockGridSize s = stock_grid_size(box, cell);
  const double limit = static_cast<double>(memory_limit);
  if (!(s.bytes <= limit) || s.nx == 0 || s.ny == 0 || s.nx > 0x7fffffffu || s.ny > 0x7fffffffu) {
    // The cell that brings the floors within the limit (the area scales with 1 / cell^2).
    // The area scales with 1 / cell^2; rounded up to 3 significant digits
    // and grown until the whole grid (cells rounded up) fits.
    double fit = cell * std::sqrt(s.bytes / std::max(limit, 1.0));
    for (int it = 0; it < 100; ++it) {
      const double p = std::pow(10.0, std::floor(std::log10(fit)) - 2);
      fit = std::ceil(fit / p) * p;
      if (stock_grid_size(box, fit).bytes <= limit) break;
      fit *= 1.001;
    }
    char counts[64];
    std::snprintf(counts, sizeof counts, "%.0f x %.0f", columns(box.x1 - box.x0, cell), columns(box.y1 - box.y0, cell));
    throw InputError(errc::stock_memory, Place::at_setting("cell"),
                     std::string("a stock grid of ") + counts + " columns at a cell of " + fmt_num(cell) + " needs " +
                         mib(s.bytes) + ", above the memory limit of " + mib(limit) + ": use a cell of at least " +
                         fmt_num(fit) + " or a smaller stock");
  }
  nx_ = s.nx;
  ny_ = s.ny;
  floors_.assign(nx_ * ny_, box.z1);
  set_threads(0);
}

void DexelGrid::set_threads(unsigned n) { threads_ = n == 0 ? std::max(1u, std::thread::hardware_concurrency()) : n; }

double DexelGrid::memory_bytes() const {
  return static_cast<double>(floors_.capacity() * sizeof(double) + ny_ * sizeof(void*) + sizeof(DexelGrid));
}

void DexelGrid::cut(const Sweep& move, const ToolShape& tool) { cut(std::span<const Sweep>(&move, 1), tool); }

void DexelGrid::cut(std::span<const Sweep> moves, const ToolShape& tool) {
  const Profile prof(tool);
  const double R = prof.R, C = cell_, x0 = box_.x0, y0 = box_.y0, z0 = box_.z0;
  const long ny = static_cast<long>(ny_), nx = static_cast<long>(nx_);
  // Rows within reach of a path whose tip stays in [ylo, yhi].
  auto rows = [&](Prepared& p, double ylo, double yhi, double zmin) {
    p.j0 = std::max(0L, static_cast<long>(std::ceil((ylo - R - y0) / C - 0.5 - 1e-9)));
    p.j1 = std::min(ny - 1, static_cast<long>(std::floor((yhi + R - y0) / C - 0.5 + 1e-9)));
    if (zmin >= box_.z1) p.j1 = -1;  // above the stock: cuts nothing
  };
  std::vector<Prepared> prep;
  prep.reserve(moves.size());
  auto add_line = [&](const Vec3& a, const Vec3& b) {
    Prepared p;
    const LinePrep l = prepare_line(a, b);
    rows(p, std::min(a.y, b.y), std::max(a.y, b.y), l.zmin);
    p.geom = l;
    if (p.j0 <= p.j1) prep.push_back(p);
  };
  for (const Sweep& m : moves) {
    switch (m.kind()) {
      case SweepKind::line: add_line(m.from(), m.to()); break;
      case SweepKind::arc: {
        Prepared p;
        const ArcPrep a = prepare_arc(m.arc());
        rows(p, a.ylo, a.yhi, a.zmin);
        p.geom = a;
        if (p.j0 <= p.j1) prep.push_back(p);
        break;
      }
      case SweepKind::polyline: {
        const auto& pts = m.points();
        if (pts.size() == 1) add_line(pts[0], pts[0]);
        for (std::size_t k = 1; k < pts.size(); ++k) add_line(pts[k - 1], pts[k]);
        added_error_ = std::max(added_error_, m.bound());
        break;
      }
    }
  }
  if (prep.empty()) return;

  // One move over one row.
  auto do_row = [&](const Prepared& p, long j, FloorStats& st) {
    const double y = y0 + (static_cast<double>(j) + 0.5) * C;
    double xlo = 0, xhi = 0;
    const bool hit = std::visit(
        [&](const auto& g) {
          if constexpr (std::is_same_v<std::decay_t<decltype(g)>, LinePrep>)
            return line_row_range(g, R, y, xlo, xhi);
          else
            return arc_row_range(g, R, y, xlo, xhi);
        },
        p.geom);
    if (!hit) return;
    const double f0 = std::ceil((xlo - x0) / C - 0.5), f1 = std::floor((xhi - x0) / C - 0.5);
    if (f1 < 0 || f0 > static_cast<double>(nx - 1)) return;
    const int i0 = static_cast<int>(std::max(0.0, f0)),
              i1 = static_cast<int>(std::min(static_cast<double>(nx - 1), f1));
    if (i0 > i1) return;
    double* row = floors_.data() + j * nx;
    if (const auto* l = std::get_if<LinePrep>(&p.geom))
      line_row(*l, prof, y, x0, C, i0, i1, row, st);
    else
      arc_row(std::get<ArcPrep>(p.geom), prof, y, x0, C, i0, i1, row, st);
    for (int i = i0; i <= i1; ++i) row[i] = std::max(row[i], z0);
  };

  std::vector<FloorStats> stats;
  double work = 0;
  for (const Prepared& p : prep) work += static_cast<double>(p.j1 - p.j0 + 1);
  const unsigned nthreads = static_cast<unsigned>(
      std::min<double>(threads_, std::max(1.0, std::floor(work / 64))));  // a few rows do not pay for a thread
  if (nthreads <= 1) {
    stats.resize(1);
    for (const Prepared& p : prep)
      for (long j = p.j0; j <= p.j1; ++j) do_row(p, j, stats[0]);
  } else {
    // Rows in chunks; each chunk takes the moves that reach it, in order.
    // A chunk is one thread's at a time, and a floor is a minimum over the
    // moves: the result is the same for any split.
    const long nchunks = (ny + kRowsPerChunk - 1) / kRowsPerChunk;
    std::vector<std::uint32_t> count(static_cast<std::size_t>(nchunks) + 1, 0);
    for (const Prepared& p : prep)
      for (long c = p.j0 / kRowsPerChunk; c <= p.j1 / kRowsPerChunk; ++c) ++count[static_cast<std::size_t>(c) + 1];
    for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
    std::vector<std::uint32_t> bucket(count.back()), fill(count.begin(), count.end() - 1);
    for (std::size_t k = 0; k < prep.size(); ++k)
      for (long c = prep[k].j0 / kRowsPerChunk; c <= prep[k].j1 / kRowsPerChunk; ++c)
        bucket[fill[static_cast<std::size_t>(c)]++] = static_cast<std::uint32_t>(k);
    std::atomic<long> next{0};
    stats.resize(nthreads);
    auto worker = [&](unsigned t) {
      for (long c; (c = next.fetch_add(1)) < nchunks;) {
        const long r0 = c * kRowsPerChunk, r1 = std::min(ny - 1, r0 + kRowsPerChunk - 1);
        for (std::uint32_t b = count[static_cast<std::size_t>(c)]; b < count[static_cast<std::size_t>(c) + 1]; ++b) {
          const Prepared& p = prep[bucket[b]];
          for (long j = std::max(r0, p.j0); j <= std::min(r1, p.j1); ++j) do_row(p, j, stats[t]);
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < nthreads; ++t) pool.emplace_back(worker, t);
    worker(0);
    for (auto& th : pool) th.join();
  }
  for (const FloorStats& s : stats) {
    stats_.columns += s.columns;
    stats_.searched_columns += s.generic_columns;
    stats_.search_intervals += s.generic_nodes;
    stats_.depth_limited += s.depth_limited;
  }
}

double DexelGrid::removed_volume() const {
  // Neumaier's compensated sum, in row order: the same for every run.
  double sum = 0, comp = 0;
  for (double f : floors_) {
    const double v = box_.z1 - f;
    const double t = sum + v;
    comp += std::abs(sum) >= std::abs(v) ? (sum - t) + v : (v - t) + sum;
    sum = t;
  }
  return (sum + comp) * cell_ * cell_;
}

DexelGrid::Deepest DexelGrid::deepest() const {
  const auto it = std::min_element(floors_.begin(), floors_.end());
  const std::size_t k = static_cast<std::size_t>(it - floors_.begin());
  Deepest d;
  d.z = *it;
  d.i = k % nx_;
  d.j = k / nx_;
  d.x = x_center(d.i);
  d.y = y_center(d.j);
  return d;
}

std::uint64_t DexelGrid::hash() const {
  std::uint64_t h = 0xcbf29ce484222325ull;
  auto feed = [&](std::int64_t v) {
    const auto u = static_cast<std::uint64_t>(v);
    for (int b = 0; b < 8; ++b) {
      h ^= (u >> (8 * b)) & 0xffu;
      h *= 0x100000001b3ull;
    }
  };
  feed(static_cast<std::int64_t>(nx_));
  feed(static_cast<std::int64_t>(ny_));
  for (double f : floors_) feed(std::llround(f * 1000));
  return h;
}

std::string DexelGrid::hash_hex() const {
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(hash()));
  return b;
}

}  // namespace bezcam
