#include "rig/GltfRig.h"

#include <tiny_gltf.h>

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cerrno>
#include <fstream>
#include <sstream>
#include <cstring>
#include <limits>

namespace medial {

namespace {

// Appends `count` elements of `bytesEach` bytes from `data` to the buffer as a new view and accessor;
// returns the accessor's index.
int addAccessor(tinygltf::Model& model, const void* data, size_t count, size_t bytesEach, int componentType,
                int type, int target) {
  std::vector<unsigned char>& buffer = model.buffers[0].data;
  while (buffer.size() % 4) buffer.push_back(0);  // every view starts 4-byte aligned
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = count * bytesEach;
  if (target) view.target = target;
  const auto* bytes = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), bytes, bytes + count * bytesEach);
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size()) - 1;
  accessor.componentType = componentType;
  accessor.count = count;
  accessor.type = type;
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

std::vector<double> columnMajor(const Eigen::Matrix4d& m) {
  std::vector<double> values(16);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) values[size_t(4 * c + r)] = m(r, c);
  return values;
}

int addNode(tinygltf::Model& model, const std::string& name, const Eigen::Matrix4d& local) {
  tinygltf::Node node;
  node.name = name;
  if (!local.isIdentity()) node.matrix = columnMajor(local);
  model.nodes.push_back(node);
  return int(model.nodes.size()) - 1;
}

}  // namespace

std::string writeGltfRig(const Rig& rig, const std::vector<RigBone>& bones,
                         const std::vector<std::vector<std::pair<int, double>>>& influences,
                         const std::string& meshName, const std::string& path, bool binary) {
  const size_t n = size_t(rig.mesh.vertices.rows());
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Medial";
  model.buffers.resize(1);
  model.buffers[0].data.reserve(n * 60 + size_t(rig.mesh.faces.rows()) * 12);

  // Positions, with the bounds the specification requires.
  std::vector<float> positions(3 * n);
  std::array<double, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (size_t v = 0; v < n; ++v)
    for (int c = 0; c < 3; ++c) {
      positions[3 * v + size_t(c)] = float(rig.mesh.vertices(Eigen::Index(v), c));
      lo[size_t(c)] = std::min(lo[size_t(c)], double(positions[3 * v + size_t(c)]));
      hi[size_t(c)] = std::max(hi[size_t(c)], double(positions[3 * v + size_t(c)]));
    }
  const int position = addAccessor(model, positions.data(), n, 12, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                   TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  model.accessors[size_t(position)].minValues = {lo[0], lo[1], lo[2]};
  model.accessors[size_t(position)].maxValues = {hi[0], hi[1], hi[2]};

  // The skin's joints: the root joint and every bone, in the bones' order - also a bone that drives no
  // vertex (a short bone beside longer ones, whose influence no vertex keeps among its four), so that the
  // file holds the whole skeleton.
  std::vector<int> jointOfBone(bones.size(), -1);
  std::vector<size_t> joints;
  for (size_t b = 0; b < bones.size(); ++b) {
    jointOfBone[b] = int(joints.size());
    joints.push_back(b);
  }
  std::vector<uint16_t> jointIds(4 * n, 0);
  std::vector<float> weights(4 * n, 0.0f);
  std::vector<uint8_t> used(n, 0);
  for (size_t b = 0; b < bones.size(); ++b) {
    if (bones[b].edge < 0 || jointOfBone[b] < 0) continue;
    for (const auto& [vertex, weight] : influences[size_t(bones[b].edge)]) {
      uint8_t& slot = used[size_t(vertex)];
      if (slot >= 4) continue;  // keptInfluences keeps at most four
      jointIds[4 * size_t(vertex) + slot] = uint16_t(jointOfBone[b]);
      weights[4 * size_t(vertex) + slot] = float(weight);
      ++slot;
    }
  }
  const int joint = addAccessor(model, jointIds.data(), n, 8, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER);
  const int weight = addAccessor(model, weights.data(), n, 16, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                 TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER);
  std::vector<uint32_t> indices(size_t(rig.mesh.faces.size()));
  for (Eigen::Index f = 0; f < rig.mesh.faces.rows(); ++f)
    for (int c = 0; c < 3; ++c) indices[size_t(3 * f + c)] = uint32_t(rig.mesh.faces(f, c));
  const int index =
      addAccessor(model, indices.data(), indices.size(), 4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                  TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  std::vector<float> inverseBind;
  for (size_t b : joints)
    for (double value : columnMajor(bones[b].global.inverse())) inverseBind.push_back(float(value));
  const int bind = addAccessor(model, inverseBind.data(), joints.size(), 64, TINYGLTF_COMPONENT_TYPE_FLOAT,
                               TINYGLTF_TYPE_MAT4, 0);

  tinygltf::Material material;
  material.name = "Material";
  model.materials.push_back(material);
  tinygltf::Primitive primitive;
  primitive.attributes = {{"POSITION", position}, {"JOINTS_0", joint}, {"WEIGHTS_0", weight}};
  primitive.indices = index;
  primitive.material = 0;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = meshName;
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);

  // Nodes: Scene -> {mesh, Armature -> Root -> bones by hierarchy}.
  const int scene = addNode(model, "Scene", Eigen::Matrix4d::Identity());
  const int meshNode = addNode(model, meshName, Eigen::Matrix4d::Identity());
  const int armature = addNode(model, "Armature", Eigen::Matrix4d::Identity());
  std::vector<int> boneNode(bones.size());
  for (size_t b = 0; b < bones.size(); ++b) {
    const RigBone& bone = bones[b];
    const Eigen::Matrix4d parentGlobal =
        bone.parent < 0 ? Eigen::Matrix4d::Identity() : bones[size_t(bone.parent)].global;
    boneNode[b] = addNode(model, bone.name, parentGlobal.inverse() * bone.global);
    const int parent = bone.parent < 0 ? armature : boneNode[size_t(bone.parent)];
    model.nodes[size_t(parent)].children.push_back(boneNode[b]);
  }
  model.nodes[size_t(scene)].children = {meshNode, armature};
  model.nodes[size_t(meshNode)].mesh = 0;
  model.nodes[size_t(meshNode)].skin = 0;
  tinygltf::Skin skin;
  skin.name = "Armature";
  skin.inverseBindMatrices = bind;
  skin.skeleton = boneNode[0];
  for (size_t b : joints) skin.joints.push_back(boneNode[b]);
  model.skins.push_back(skin);
  tinygltf::Scene root;
  root.nodes = {scene};
  model.scenes.push_back(root);
  model.defaultScene = 0;

  // To a stream, then the file: TinyGLTF's own file writing reports no I/O error.
  std::ostringstream bytes;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, bytes, !binary, binary)) return "cannot encode the rig as glTF";
  const std::string data = bytes.str();
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file || !file.write(data.data(), std::streamsize(data.size())) || !file.flush())
    return "cannot write the rig to " + path + ": " + std::strerror(errno);
  return {};
}

}  // namespace medial
