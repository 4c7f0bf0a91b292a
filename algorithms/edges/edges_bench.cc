// Single-thread speed of the colour edge extraction on a synthetic
// 2048 x 2048 aerial scene, with OpenCV's LSD on the grey image beside it.
// Reports ms per megapixel as a counter.

#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "algorithms/edges/extract_segments.h"
#include "algorithms/edges/synthetic_images.h"

namespace roofsweep {
namespace {

const cv::Mat& Scene() {
  static const cv::Mat scene = testing::RenderRoofScene(cv::Size(2048, 2048), 2024);
  return scene;
}

void SetCounters(benchmark::State& state, double segments) {
  const double mp = Scene().total() / 1e6;
  state.counters["ms_per_MP"] = benchmark::Counter(
      mp / 1e3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["segments"] = segments;
}

void BM_ExtractSegments(benchmark::State& state, GradientMethod method) {
  cv::setNumThreads(1);
  const cv::Mat& image = Scene();
  EdgeOptions o;
  o.method = method;
  size_t n = 0;
  for (auto _ : state) {
    const Segments2D s = ExtractSegments(image, o);
    n = s.size();
    benchmark::DoNotOptimize(s.data());
  }
  SetCounters(state, static_cast<double>(n));
}

void BM_OpenCvLsdGrey(benchmark::State& state) {
  cv::setNumThreads(1);
  cv::Mat grey8;
  cv::Mat grey;
  cv::cvtColor(Scene(), grey, cv::COLOR_RGB2GRAY);
  grey.convertTo(grey8, CV_8U, 255.0);
  const cv::Ptr<cv::LineSegmentDetector> lsd = cv::createLineSegmentDetector();
  std::vector<cv::Vec4f> lines;
  for (auto _ : state) {
    lines.clear();
    lsd->detect(grey8, lines);
    benchmark::DoNotOptimize(lines.data());
  }
  SetCounters(state, static_cast<double>(lines.size()));
}

BENCHMARK_CAPTURE(BM_ExtractSegments, max, GradientMethod::kMax)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExtractSegments, dizenzo, GradientMethod::kDiZenzo)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExtractSegments, grey, GradientMethod::kGrey)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OpenCvLsdGrey)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace roofsweep
