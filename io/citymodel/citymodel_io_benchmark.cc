// Writes N procedural buildings to each format through the streaming
// writers, generating each building on the fly so that only the writer's own
// memory shows. Counters: rss_growth_MB = largest increase of the resident
// set over the value after Begin (sampled every 250 buildings);
// peak_rss_MB = getrusage's ru_maxrss for the whole process so far.
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/citymodel/citymodel_io.h"
#include "io/citymodel/procedural_buildings.h"

namespace {

using namespace roofsweep;

double CurrentRssMb() {
  long pages = 0, resident = 0;
  std::ifstream in("/proc/self/statm");
  in >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1048576.0;
}

double PeakRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // KiB on Linux
}

const char* kExt[] = {".gml", ".city.json", ".city.jsonl", ".gpkg", ".fgb"};
const char* kName[] = {"CityGML", "CityJSON", "CityJSONSeq", "GPKG", "FlatGeobuf"};

void BM_WriteCity(benchmark::State& state) {
  const int format = static_cast<int>(state.range(0));
  const int n = static_cast<int>(state.range(1));
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("rs_citymodel_bench_" + std::to_string(getpid())))
          .string();
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/city" + kExt[format];
  const int cols = testing::CityColumns(n);
  Envelope3 env;
  env << 500000, 5400000, 100, 500000 + 20.0 * cols, 5400000 + 20.0 * cols, 120;
  WriteOptions options;
  options.overwrite = true;
  double growth = 0;
  for (auto _ : state) {
    auto writer = OpenCityModelWriter(path, options);
    writer->Begin("EPSG:25832", env);
    const double base = CurrentRssMb();
    for (int i = 0; i < n; ++i) {
      writer->Write(testing::MakeCityBuilding(i, cols));
      if (i % 250 == 0) growth = std::max(growth, CurrentRssMb() - base);
    }
    growth = std::max(growth, CurrentRssMb() - base);
    writer->End();
  }
  state.SetLabel(kName[format]);
  state.counters["buildings_per_s"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["rss_growth_MB"] = growth;
  state.counters["peak_rss_MB"] = PeakRssMb();
  state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1048576.0;
  std::filesystem::remove_all(dir);
}

BENCHMARK(BM_WriteCity)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {1000, 10000}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
