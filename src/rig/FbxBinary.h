/// \file
/// FbxBinary: a binary FBX 7.4 document as a tree of records, and its encoding. The format is public by
/// description only (Blender's io_scene_fbx and the "FBX binary file format specification" note of 2013): a
/// 27-byte header, then records of {end offset, property count, property bytes, name, typed properties,
/// nested records}, a 13-byte null record closing every nested list and the top level, then a footer.
/// Assimp's FBX exporter writes files Blender refuses, so Medial writes the records itself.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace medial::fbx {

/// A raw property (FBX type 'R'): bytes.
struct Raw {
  std::string bytes;  ///< the bytes as they are
};

/// One typed property: C (bool), I (int32), L (int64), D (double), S (string), R (raw), and the arrays
/// i, l, d (written uncompressed).
using Property = std::variant<bool, int32_t, int64_t, double, std::string, Raw, std::vector<int32_t>,
                              std::vector<int64_t>, std::vector<double>>;

/// One FBX record: a name, its properties and its nested records.
struct Node {
  std::string name;                  ///< the record's name ("Objects", "Model", ...)
  std::vector<Property> properties;  ///< its properties, in order
  std::vector<Node> children;        ///< its nested records

  /// Appends a child record and returns it.
  Node& add(const std::string& childName, std::vector<Property> childProperties = {});
  /// A "P" entry of a Properties70 list: name, type, label, flags, then the values.
  Node& addProperty70(const std::string& property, const std::string& type, const std::string& label,
                      const std::string& flags, std::vector<Property> values);
};

/// The whole file: header (version 7400), the top-level records, the null record, the footer.
std::string encode(const std::vector<Node>& topLevel);

/// FBX names an object "Name\x00\x01Class" in its second property.
std::string objectName(const std::string& name, const std::string& objectClass);

}  // namespace medial::fbx
