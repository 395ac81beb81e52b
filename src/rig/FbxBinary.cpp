#include "rig/FbxBinary.h"

#include <cstring>
#include <stdexcept>

namespace medial::fbx {

namespace {

constexpr uint32_t kVersion = 7400;
constexpr size_t kNullRecord = 13;  // end offset, property count, property bytes (3 x 4), name length (1)
const char kHeader[] = "Kaydara FBX Binary  \0\x1a\0";  // 23 bytes, then the version
// The footer Blender and the FBX SDK write for the fixed file id and creation time below.
const unsigned char kFooterId[16] = {0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66,
                                     0xb1, 0x76, 0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e};
const unsigned char kFooterMagic[16] = {0xf8, 0x5a, 0x8c, 0x6a, 0xde, 0xf5, 0xd9, 0x7e,
                                        0xec, 0xe9, 0x0c, 0xe3, 0x75, 0x8f, 0x29, 0x0b};

template <typename T>
void put(std::string& out, T value) {  // little-endian, as on every machine Debian's amd64 runs on
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

template <typename T>
void putArray(std::string& out, char type, const std::vector<T>& values) {
  out += type;
  put<uint32_t>(out, uint32_t(values.size()));
  put<uint32_t>(out, 0);  // encoding: raw
  put<uint32_t>(out, uint32_t(values.size() * sizeof(T)));
  for (const T& v : values) put<T>(out, v);
}

void putProperty(std::string& out, const Property& property) {
  struct Visitor {
    std::string& out;
    void operator()(bool v) const {
      out += 'C';
      out += char(v ? 1 : 0);
    }
    void operator()(int32_t v) const {
      out += 'I';
      put(out, v);
    }
    void operator()(int64_t v) const {
      out += 'L';
      put(out, v);
    }
    void operator()(double v) const {
      out += 'D';
      put(out, v);
    }
    void operator()(const std::string& v) const {
      out += 'S';
      put<uint32_t>(out, uint32_t(v.size()));
      out += v;
    }
    void operator()(const Raw& v) const {
      out += 'R';
      put<uint32_t>(out, uint32_t(v.bytes.size()));
      out += v.bytes;
    }
    void operator()(const std::vector<int32_t>& v) const { putArray(out, 'i', v); }
    void operator()(const std::vector<int64_t>& v) const { putArray(out, 'l', v); }
    void operator()(const std::vector<double>& v) const { putArray(out, 'd', v); }
  };
  std::visit(Visitor{out}, property);
}

// Appends `node` at out.size() (its absolute offset in the file): the end offset is patched in last.
void putNode(std::string& out, const Node& node) {
  if (node.name.size() > 255) throw std::length_error("FBX record name longer than 255 bytes");
  const size_t start = out.size();
  put<uint32_t>(out, 0);  // end offset, below
  put<uint32_t>(out, uint32_t(node.properties.size()));
  put<uint32_t>(out, 0);  // property bytes, below
  out += char(node.name.size());
  out += node.name;
  const size_t propertiesStart = out.size();
  for (const Property& p : node.properties) putProperty(out, p);
  const uint32_t propertyBytes = uint32_t(out.size() - propertiesStart);
  for (const Node& child : node.children) putNode(out, child);
  // A nested list ends with a null record; so does a record without properties (as the SDK writes).
  if (!node.children.empty() || node.properties.empty()) out.append(kNullRecord, '\0');
  if (out.size() > UINT32_MAX) throw std::length_error("FBX 7.4 files are limited to 4 GB");
  const uint32_t end = uint32_t(out.size());
  std::memcpy(&out[start], &end, 4);
  std::memcpy(&out[start + 8], &propertyBytes, 4);
}

}  // namespace

Node& Node::add(const std::string& childName, std::vector<Property> childProperties) {
  children.push_back(Node{childName, std::move(childProperties), {}});
  return children.back();
}

Node& Node::addProperty70(const std::string& property, const std::string& type, const std::string& label,
                          const std::string& flags, std::vector<Property> values) {
  std::vector<Property> all{property, type, label, flags};
  all.insert(all.end(), values.begin(), values.end());
  return add("P", std::move(all));
}

std::string encode(const std::vector<Node>& topLevel) {
  std::string out(kHeader, sizeof kHeader - 1);
  put<uint32_t>(out, kVersion);
  for (const Node& node : topLevel) putNode(out, node);
  out.append(kNullRecord, '\0');
  out.append(reinterpret_cast<const char*>(kFooterId), sizeof kFooterId);
  out.append(4, '\0');
  const size_t pad = 16 - out.size() % 16;  // 1 to 16 bytes to the next multiple of 16
  out.append(pad, '\0');
  put<uint32_t>(out, kVersion);
  out.append(120, '\0');
  out.append(reinterpret_cast<const char*>(kFooterMagic), sizeof kFooterMagic);
  return out;
}

std::string objectName(const std::string& name, const std::string& objectClass) {
  return name + std::string("\x00\x01", 2) + objectClass;
}

}  // namespace medial::fbx
