#include "rig/FbxRig.h"

#include "rig/FbxBinary.h"

#include <Eigen/Geometry>

#include <cmath>

namespace medial {

namespace {

using fbx::Node;
using fbx::objectName;

std::vector<double> matrixArray(const Eigen::Matrix4d& m) {  // FBX stores matrices column by column
  return std::vector<double>(m.data(), m.data() + 16);
}

// Lcl Translation / Rotation / Scaling of a local transform; FBX's default rotation order XYZ means
// R = Rz * Ry * Rx, in degrees.
void addLocalTransform(Node& properties, const Eigen::Matrix4d& local) {
  const Eigen::Vector3d t = local.topRightCorner<3, 1>();
  const Eigen::Vector3d zyx =
      Eigen::Matrix3d(local.topLeftCorner<3, 3>()).eulerAngles(2, 1, 0) * (180.0 / M_PI);
  properties.addProperty70("Lcl Translation", "Lcl Translation", "", "A", {t.x(), t.y(), t.z()});
  properties.addProperty70("Lcl Rotation", "Lcl Rotation", "", "A", {zyx[2], zyx[1], zyx[0]});
  properties.addProperty70("Lcl Scaling", "Lcl Scaling", "", "A", {1.0, 1.0, 1.0});
}

Node headerExtension() {
  Node header{"FBXHeaderExtension", {}, {}};
  header.add("FBXHeaderVersion", {int32_t(1003)});
  header.add("FBXVersion", {int32_t(7400)});
  Node& stamp = header.add("CreationTimeStamp");
  const std::pair<const char*, int32_t> fields[] = {{"Version", 1000}, {"Year", 1970},    {"Month", 1},
                                                    {"Day", 1},        {"Hour", 10},      {"Minute", 0},
                                                    {"Second", 0},     {"Millisecond", 0}};
  for (const auto& [name, value] : fields) stamp.add(name, {value});
  header.add("Creator", {std::string("Medial")});
  return header;
}

Node globalSettings() {
  Node settings{"GlobalSettings", {}, {}};
  settings.add("Version", {int32_t(1000)});
  Node& p = settings.add("Properties70");
  const std::pair<const char*, int32_t> axes[] = {
      {"UpAxis", 1},    {"UpAxisSign", 1},    {"FrontAxis", 2},      {"FrontAxisSign", 1},
      {"CoordAxis", 0}, {"CoordAxisSign", 1}, {"OriginalUpAxis", 1}, {"OriginalUpAxisSign", 1}};
  for (const auto& [name, value] : axes) p.addProperty70(name, "int", "Integer", "", {value});
  p.addProperty70("UnitScaleFactor", "double", "Number", "", {100.0});
  p.addProperty70("OriginalUnitScaleFactor", "double", "Number", "", {100.0});
  return settings;
}

Node definitions(int models, int attributes, int deformers) {
  Node d{"Definitions", {}, {}};
  d.add("Version", {int32_t(100)});
  const std::pair<const char*, int> types[] = {{"GlobalSettings", 1},   {"Model", models},
                                               {"Geometry", 1},         {"NodeAttribute", attributes},
                                               {"Deformer", deformers}, {"Pose", 1}};
  int total = 0;
  for (const auto& [name, count] : types) total += count;
  d.add("Count", {int32_t(total)});
  for (const auto& [name, count] : types)
    d.add("ObjectType", {std::string(name)}).add("Count", {int32_t(count)});
  return d;
}

Node model(int64_t id, const std::string& name, const std::string& type, const Eigen::Matrix4d& local) {
  Node m{"Model", {id, objectName(name, "Model"), type}, {}};
  m.add("Version", {int32_t(232)});
  addLocalTransform(m.add("Properties70"), local);
  m.add("Shading", {true});
  m.add("Culling", {std::string("CullingOff")});
  return m;
}

}  // namespace

std::string fbxRigFile(const Rig& rig, const std::vector<RigBone>& bones,
                       const std::vector<std::vector<std::pair<int, double>>>& influences,
                       const std::string& meshName) {
  int64_t nextId = 1000000;
  Node objects{"Objects", {}, {}}, connections{"Connections", {}, {}};
  auto connect = [&](int64_t child, int64_t parent) {
    connections.add("C", {std::string("OO"), child, parent});
  };

  // The mesh: a Geometry (triangles; FBX marks a polygon's last corner as -(index + 1)) under a Model.
  const int64_t geometryId = nextId++, meshId = nextId++;
  Node& geometry =
      objects.add("Geometry", {geometryId, objectName(meshName, "Geometry"), std::string("Mesh")});
  std::vector<double> vertices(rig.mesh.vertices.data(), rig.mesh.vertices.data() + rig.mesh.vertices.size());
  std::vector<int32_t> corners;
  for (Eigen::Index f = 0; f < rig.mesh.faces.rows(); ++f)
    corners.insert(corners.end(), {rig.mesh.faces(f, 0), rig.mesh.faces(f, 1), -rig.mesh.faces(f, 2) - 1});
  geometry.add("Vertices", {std::move(vertices)});
  geometry.add("PolygonVertexIndex", {std::move(corners)});
  geometry.add("GeometryVersion", {int32_t(124)});
  objects.children.push_back(model(meshId, meshName, "Mesh", Eigen::Matrix4d::Identity()));
  connect(meshId, 0);
  connect(geometryId, meshId);

  // The armature: a Null holding the joints, then one LimbNode per joint (the root joint first).
  const int64_t armatureId = nextId++, armatureAttribute = nextId++;
  objects.children.push_back(model(armatureId, "Armature", "Null", Eigen::Matrix4d::Identity()));
  objects
      .add("NodeAttribute", {armatureAttribute, objectName("Armature", "NodeAttribute"), std::string("Null")})
      .add("TypeFlags", {std::string("Null")});
  connect(armatureId, 0);
  connect(armatureAttribute, armatureId);
  std::vector<int64_t> boneIds;
  for (const RigBone& bone : bones) {
    const int64_t id = nextId++, attribute = nextId++;
    boneIds.push_back(id);
    const Eigen::Matrix4d parent =
        bone.parent < 0 ? Eigen::Matrix4d::Identity() : bones[size_t(bone.parent)].global;
    objects.children.push_back(model(id, bone.name, "LimbNode", parent.inverse() * bone.global));
    objects.add("NodeAttribute", {attribute, objectName(bone.name, "NodeAttribute"), std::string("LimbNode")})
        .add("TypeFlags", {std::string("Skeleton")});
    connect(id, bone.parent < 0 ? armatureId : boneIds[size_t(bone.parent)]);
    connect(attribute, id);
  }

  // The skin: one Cluster per bone, empty for a bone that drives no vertex (importers find a skin's bones
  // by its clusters, and the file should hold the whole skeleton). Transform takes the mesh into the bone's
  // rest frame, TransformLink is the bone's rest frame (the mesh sits at the origin).
  const int64_t skinId = nextId++;
  Node& skin = objects.add("Deformer", {skinId, objectName(meshName, "Deformer"), std::string("Skin")});
  skin.add("Version", {int32_t(101)});
  skin.add("Link_DeformAcuracy", {50.0});
  connect(skinId, geometryId);
  int clusters = 0;
  for (size_t b = 0; b < bones.size(); ++b) {
    if (bones[b].edge < 0) continue;
    const int64_t clusterId = nextId++;
    Node& cluster = objects.add(
        "Deformer", {clusterId, objectName(bones[b].name, "SubDeformer"), std::string("Cluster")});
    cluster.add("Version", {int32_t(100)});
    cluster.add("UserData", {std::string(), std::string()});
    std::vector<int32_t> indexes;
    std::vector<double> weights;
    for (const auto& [vertex, weight] : influences[size_t(bones[b].edge)]) {
      indexes.push_back(vertex);
      weights.push_back(weight);
    }
    cluster.add("Indexes", {std::move(indexes)});
    cluster.add("Weights", {std::move(weights)});
    cluster.add("Transform", {matrixArray(bones[b].global.inverse())});
    cluster.add("TransformLink", {matrixArray(bones[b].global)});
    connect(clusterId, skinId);
    connect(boneIds[b], clusterId);
    ++clusters;
  }

  // The bind pose: every joint's and the mesh's rest frame, in mesh space.
  Node& pose = objects.add("Pose", {nextId++, objectName(meshName, "Pose"), std::string("BindPose")});
  pose.add("Type", {std::string("BindPose")});
  pose.add("Version", {int32_t(100)});
  pose.add("NbPoseNodes", {int32_t(bones.size() + 1)});
  Node& meshPose = pose.add("PoseNode");
  meshPose.add("Node", {meshId});
  meshPose.add("Matrix", {matrixArray(Eigen::Matrix4d::Identity())});
  for (size_t b = 0; b < bones.size(); ++b) {
    Node& node = pose.add("PoseNode");
    node.add("Node", {boneIds[b]});
    node.add("Matrix", {matrixArray(bones[b].global)});
  }

  std::vector<Node> file;
  file.push_back(headerExtension());
  file.push_back(
      Node{"FileId",
           {fbx::Raw{std::string("\x28\xb3\x2a\xeb\xb6\x24\xcc\xc2\xbf\xc8\xb0\x2a\xa9\x2b\xfc\xf1", 16)}},
           {}});
  file.push_back(Node{"CreationTime", {std::string("1970-01-01 10:00:00:000")}, {}});
  file.push_back(Node{"Creator", {std::string("Medial")}, {}});
  file.push_back(globalSettings());
  Node documents{"Documents", {}, {}};
  documents.add("Count", {int32_t(1)});
  Node& document = documents.add("Document", {nextId++, std::string("Scene"), std::string("Scene")});
  document.add("Properties70");
  document.add("RootNode", {int64_t(0)});
  file.push_back(documents);
  file.push_back(Node{"References", {}, {}});
  file.push_back(definitions(int(bones.size()) + 2, int(bones.size()) + 1, clusters + 1));
  file.push_back(objects);
  file.push_back(connections);
  Node takes{"Takes", {}, {}};
  takes.add("Current", {std::string()});
  file.push_back(takes);
  return fbx::encode(file);
}

}  // namespace medial
