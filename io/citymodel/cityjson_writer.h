#pragma once

#include <cstdio>
#include <memory>
#include <string>

#include "io/citymodel/citymodel_writer.h"
#include "io/citymodel/output_file.h"

namespace roofsweep {

// CityJSON 2.0 (https://www.cityjson.org/specs/2.0.1/). Coordinates are
// integers with transform scale 0.001 (1e-8 for geographic x, y) and
// translate = floor of the envelope minimum; referenceSystem is the OGC URL
// for an EPSG CRS. Each Building has one Solid lod "2" with semantics (one
// semantic object per Surface, carrying its id), and attributes
// measuredHeight, roofType (SIG3D code as string) and the generic ones.
// A building's parts are BuildingPart objects written the same way, listed
// in its "children" and naming it in "parents".
//
// A CityJSON file has one vertex list for all objects, so this writer keeps
// the document in memory until End(); use CityJsonSeqWriter to stream.
class CityJsonWriter final : public CityModelStreamWriter {
 public:
  CityJsonWriter(const std::string& path, const CityModelWriteOptions& options = {});
  ~CityJsonWriter() override;
  void Begin(const std::string& crs, const Envelope3& envelope) override;
  void Write(const Building& building) override;
  void End() override;

  struct State;

 private:
  CityModelWriteOptions options_;
  OutputFile file_;
  size_t count_ = 0;
  std::unique_ptr<State> state_;
};

// CityJSON Text Sequences (.city.jsonl): a first line with the CityJSON
// header (transform, metadata, empty CityObjects and vertices), then one
// CityJSONFeature per building with its own vertex list. Memory stays
// constant with the number of buildings.
class CityJsonSeqWriter final : public CityModelStreamWriter {
 public:
  CityJsonSeqWriter(const std::string& path, const CityModelWriteOptions& options = {});
  ~CityJsonSeqWriter() override;
  void Begin(const std::string& crs, const Envelope3& envelope) override;
  void Write(const Building& building) override;
  void End() override;

 private:
  CityModelWriteOptions options_;
  OutputFile file_;
  std::FILE* out_ = nullptr;
  size_t count_ = 0;
  std::unique_ptr<CityJsonWriter::State> state_;
};

}  // namespace roofsweep
