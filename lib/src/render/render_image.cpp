#include "implicitizer/render/render_image.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/memory_account.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/render/render_curve.hpp"

namespace implicitizer {
namespace {

// Counts one worker gathers, merged under the lock at the end (no contention per ray).
struct WorkerStats {
  std::uint64_t hits = 0, out_of_steps = 0, evaluations = 0, shading_evaluations = 0;
  std::uint32_t max_evaluations = 0;
};

class TileRenderer {
 public:
  TileRenderer(const RenderTarget& target, const RenderParams& settings, const Budget& budget, Image& image)
      : target_(target),
        settings_(settings),
        budget_(budget),
        camera_(settings.camera, settings.width, settings.height),
        image_(image),
        tiles_x_((settings.width + settings.tile_size - 1) / settings.tile_size),
        tiles_y_((settings.height + settings.tile_size - 1) / settings.tile_size) {}

  std::size_t tile_count() const { return tiles_x_ * tiles_y_; }

  // Takes tiles until none are left or the render stops; any exception stops all.
  void run_worker(WorkerStats& stats) {
    try {
      for (;;) {
        if (stopped_.load(std::memory_order_relaxed)) return;
        const std::size_t tile = next_tile_.fetch_add(1, std::memory_order_relaxed);
        if (tile >= tile_count()) return;
        budget_.check("render");
        render_tile(tile, stats);
        tiles_done_.fetch_add(1, std::memory_order_relaxed);
      }
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      stopped_.store(true, std::memory_order_relaxed);
    }
  }

  // Rethrows what stopped the render; a budget's LimitExceeded says how far it got.
  void rethrow_error() const {
    if (!error_) return;
    try {
      std::rethrow_exception(error_);
    } catch (const LimitExceeded& e) {
      throw LimitExceeded(e.limit(), std::string(e.what()) + " (render stopped after " +
                                         std::to_string(tiles_done_.load()) + " of " + std::to_string(tile_count()) +
                                         " tiles)");
    }
  }

 private:
  void render_tile(std::size_t tile, WorkerStats& stats) {
    const std::size_t size = settings_.tile_size;
    const std::size_t x0 = (tile % tiles_x_) * size, y0 = (tile / tiles_x_) * size;
    const std::size_t x1 = std::min(x0 + size, settings_.width), y1 = std::min(y0 + size, settings_.height);
    const std::uint32_t aa = settings_.antialiasing;
    const double samples = static_cast<double>(aa) * aa;
    for (std::size_t y = y0; y < y1; ++y) {
      for (std::size_t x = x0; x < x1; ++x) {
        std::array<double, 3> sum{0, 0, 0};
        for (std::uint32_t sy = 0; sy < aa; ++sy) {
          for (std::uint32_t sx = 0; sx < aa; ++sx) {
            const Ray ray =
                camera_.ray_through(static_cast<double>(x) + (sx + 0.5) / aa, static_cast<double>(y) + (sy + 0.5) / aa);
            const MarchResult r = march_ray(target_, ray, settings_.method, settings_.march, budget_);
            stats.evaluations += r.evaluations;
            stats.max_evaluations = std::max(stats.max_evaluations, r.evaluations);
            if (r.out_of_steps) ++stats.out_of_steps;
            std::array<double, 3> colour = settings_.shading.background;
            if (r.hit) {
              ++stats.hits;
              colour = shade_hit(target_, ray, r.t, settings_.shading, &stats.shading_evaluations);
            }
            for (std::size_t c = 0; c < 3; ++c) sum[c] += colour[c];
          }
        }
        image_.set_pixel(
            x, y,
            {to_display_byte(sum[0] / samples), to_display_byte(sum[1] / samples), to_display_byte(sum[2] / samples)});
      }
    }
  }

  const RenderTarget& target_;
  const RenderParams& settings_;
  const Budget& budget_;
  const Camera camera_;
  Image& image_;
  const std::size_t tiles_x_, tiles_y_;
  std::atomic<std::size_t> next_tile_{0}, tiles_done_{0};
  std::atomic<bool> stopped_{false};
  std::mutex mutex_;
  std::exception_ptr error_;
};

}  // namespace

CameraSpec default_camera(const RenderTarget& target, double aspect) {
  CameraSpec spec;
  const auto& lo = target.box_lo();
  const auto& hi = target.box_hi();
  const double radius = 0.5 * std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                        (hi[2] - lo[2]) * (hi[2] - lo[2]));
  // The image plane has height 1 at distance focal: tan(α) = (min(1, aspect)/2)/focal.
  const double half_extent = std::isfinite(aspect) && aspect > 0 ? std::min(1.0, aspect) / 2 : 0.5;
  const double sin_alpha = half_extent / std::hypot(half_extent, spec.focal_distance);
  const double distance = radius / sin_alpha;
  const double norm = std::sqrt(3.0 * 3 + 3 * 3 + 5 * 5);
  const auto& c = target.box_centre();
  spec.target = c;
  spec.eye = {c[0] + distance * 3 / norm, c[1] + distance * 3 / norm, c[2] + distance * 5 / norm};
  return spec;
}

CameraSpec seed_camera(const RenderTarget& target) {
  CameraSpec spec;
  const double unit = target.length_unit();
  const auto& c = target.box_centre();
  spec.target = c;
  spec.eye = {c[0] + 3 * unit, c[1] + 3 * unit, c[2] + 5 * unit};
  return spec;
}

MarchParams default_render_march_params(const RenderTarget& target, const CameraSpec& camera) {
  MarchParams params = default_march_params(target);
  const auto& c = target.box_centre();
  const double dx = camera.eye[0] - c[0], dy = camera.eye[1] - c[1], dz = camera.eye[2] - c[2];
  params.t_max += std::sqrt(dx * dx + dy * dy + dz * dz);
  return params;
}

RenderResult render_image(const RenderTarget& target, const RenderParams& settings, const Budget& budget) {
  if (target.dimension() == 2) return render_curve(target, settings.width, settings.height, CurveStyle{}, budget);
  if (settings.antialiasing == 0 || settings.antialiasing > 8) {
    throw InputError("invalid_value", "antialiasing must be 1 to 8 (AA×AA samples per pixel)").in_field("aa");
  }
  if (settings.tile_size == 0)
    throw InputError("invalid_value", "the tile size must be positive").in_field("tile_size");
  if (!is_method_applicable(settings.method, target)) {
    throw InputError("method_not_applicable",
                     std::string("method '") + to_string(settings.method) +
                         "' needs an algebraic surface: an implicit equation, a parametric surface, or a scene "
                         "that is one polynomial leaf")
        .in_field("method");
  }
  // The image is allocated whole: refuse sizes no preview needs before allocating.
  if (settings.width > 16384 || settings.height > 16384 || settings.width * settings.height > (std::size_t{1} << 26)) {
    throw InputError("invalid_size", "at most 16384 pixels a side and 2^26 pixels in all").in_field("size");
  }
  const Stopwatch timer;
  RenderResult result;
  result.image = Image(settings.width, settings.height);  // sizes checked by the camera below
  TileRenderer renderer(target, settings, budget, result.image);

  std::size_t threads = settings.threads ? settings.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = std::min(threads, renderer.tile_count());
  std::vector<WorkerStats> stats(threads);
  std::vector<std::thread> workers;
  workers.reserve(threads - 1);
  MemoryAccount* const account = current_memory_account();
  for (std::size_t i = 1; i < threads; ++i) {
    workers.emplace_back([&, i] {
      const MemoryScope scope(account);
      renderer.run_worker(stats[i]);
    });
  }
  renderer.run_worker(stats[0]);  // the calling thread works too
  for (std::thread& w : workers) w.join();
  renderer.rethrow_error();

  RenderStats& s = result.stats;
  s.width = settings.width;
  s.height = settings.height;
  s.method = settings.method;
  s.mode = target.mode();
  s.threads = threads;
  s.rays = static_cast<std::uint64_t>(settings.width) * settings.height * settings.antialiasing * settings.antialiasing;
  for (const WorkerStats& w : stats) {
    s.hits += w.hits;
    s.out_of_steps += w.out_of_steps;
    s.evaluations += w.evaluations;
    s.shading_evaluations += w.shading_evaluations;
    s.max_evaluations = std::max(s.max_evaluations, w.max_evaluations);
  }
  s.elapsed_ms = timer.elapsed_ms();
  return result;
}

}  // namespace implicitizer
