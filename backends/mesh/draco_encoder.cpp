#include "backends/mesh/draco_encoder.h"

#include <draco/compression/expert_encode.h>
#include <draco/mesh/mesh.h>

#include <stdexcept>

namespace ramus::mesh {
namespace {

draco::GeometryAttribute::Type draco_type(DracoKind k) {
  switch (k) {
    case DracoKind::kPosition:
      return draco::GeometryAttribute::POSITION;
    case DracoKind::kNormal:
      return draco::GeometryAttribute::NORMAL;
    case DracoKind::kTexCoord:
      return draco::GeometryAttribute::TEX_COORD;
    case DracoKind::kGeneric:
      break;
  }
  return draco::GeometryAttribute::GENERIC;
}

draco::DataType data_type(const DracoAttribute& a) {
  if (a.is_float) return draco::DT_FLOAT32;
  return a.component_bytes == 1 ? draco::DT_UINT8 : draco::DT_UINT16;
}

}  // namespace

DracoPrimitive draco_encode(const std::vector<DracoAttribute>& attributes, std::size_t count,
                            const std::vector<std::uint32_t>& indices) {
  draco::Mesh mesh;
  mesh.set_num_points(std::uint32_t(count));
  for (std::size_t f = 0; f + 2 < indices.size(); f += 3) {
    mesh.AddFace({draco::PointIndex(indices[f]), draco::PointIndex(indices[f + 1]),
                  draco::PointIndex(indices[f + 2])});
  }
  std::vector<int> ids;
  for (const DracoAttribute& a : attributes) {
    const std::size_t element = std::size_t(a.components) * a.component_bytes;
    if (a.data.size() != element * count)
      throw std::runtime_error("draco: attribute " + a.name + " has the wrong size");
    draco::GeometryAttribute ga;
    ga.Init(draco_type(a.kind), nullptr, std::uint8_t(a.components), data_type(a), false,
            std::int64_t(element), 0);
    const int id = mesh.AddAttribute(ga, true, std::uint32_t(count));
    draco::PointAttribute* pa = mesh.attribute(id);
    for (std::size_t i = 0; i < count; ++i)
      pa->SetAttributeValue(draco::AttributeValueIndex(std::uint32_t(i)), &a.data[i * element]);
    ids.push_back(id);
  }
  draco::ExpertEncoder encoder(mesh);
  for (std::size_t k = 0; k < attributes.size(); ++k) {
    if (attributes[k].is_float && attributes[k].quantization_bits > 0)
      encoder.SetAttributeQuantization(ids[k], attributes[k].quantization_bits);
  }
  // Speed 3 of 0 (smallest) .. 10 (fastest): Edgebreaker with its better predictors; decoding
  // stays well below the loading of the textures.
  encoder.SetSpeedOptions(3, 3);
  encoder.SetTrackEncodedProperties(true);  // for num_encoded_points / faces
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodeToBuffer(&buffer);
  if (!status.ok()) throw std::runtime_error(std::string("draco: ") + status.error_msg());
  DracoPrimitive out;
  out.bytes.assign(buffer.data(), buffer.size());
  for (std::size_t k = 0; k < attributes.size(); ++k)
    out.attribute_id[attributes[k].name] = int(mesh.attribute(ids[k])->unique_id());
  out.points = encoder.num_encoded_points();
  out.faces = encoder.num_encoded_faces();
  return out;
}

}  // namespace ramus::mesh
