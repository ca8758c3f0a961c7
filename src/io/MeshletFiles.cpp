#include "io/MeshletFiles.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include <nlohmann/json.hpp>

#include "io/FileChecks.h"

namespace conescope {

namespace {

constexpr char kMagic[8] = {'M', 'E', 'S', 'H', 'L', 'E', 'T', 'S'};
constexpr size_t kHeaderBytes = 32, kMeshletBytes = 16, kBoundsBytes = 48;
// A hierarchy's binary form: its own magic, the same header size and meshlet arrays, then 8-byte
// aligned records per cluster and per group (docs/user/engine-meshlets.md).
constexpr char kHierarchyMagic[8] = {'C', 'L', 'U', 'S', 'T', 'L', 'O', 'D'};
constexpr size_t kClusterRecordBytes = 56, kGroupRecordBytes = 48;

// --- JSON ------------------------------------------------------------------------------------------

using Json = nlohmann::json;

[[noreturn]] void failJson(const std::string& source, const std::string& where, const std::string& what) {
    throw MeshletFileError(source + ": " + where + ": " + what);
}

const Json& member(const Json& object, const char* key, const std::string& source, const std::string& where = "the document") {
    const auto found = object.find(key);
    if (found == object.end()) failJson(source, where, std::string("has no \"") + key + "\"");
    return *found;
}

const Json& arrayMember(const Json& object, const char* key, const std::string& source, const std::string& where = "the document") {
    const Json& value = member(object, key, source, where);
    if (!value.is_array()) failJson(source, std::string("\"") + key + "\"", "is not an array");
    return value;
}

// A whole number in [low, high], or an error naming where it is.
int64_t wholeNumber(const Json& value, int64_t low, int64_t high, const std::string& source, const std::string& where) {
    int64_t number = 0;
    if (value.is_number_unsigned() && value.get<uint64_t>() <= uint64_t(std::numeric_limits<int64_t>::max()))
        number = int64_t(value.get<uint64_t>());
    else if (value.is_number_integer())
        number = value.get<int64_t>();
    else
        failJson(source, where, "is " + std::string(value.type_name()) + ", not a whole number");
    if (number < low || number > high)
        failJson(source, where, std::to_string(number) + " is outside [" + std::to_string(low) + ", " + std::to_string(high) + "]");
    return number;
}

float finiteFloat(const Json& value, const std::string& source, const std::string& where) {
    if (!value.is_number()) failJson(source, where, "is " + std::string(value.type_name()) + ", not a number");
    const double number = value.get<double>();
    if (!std::isfinite(number) || std::abs(number) > double(std::numeric_limits<float>::max()))
        failJson(source, where, "is not a finite float");
    return float(number);
}

template <size_t N, typename Read>
auto fixedArray(const Json& object, const char* key, const std::string& source, const std::string& where, Read read) {
    const Json& values = member(object, key, source, where);
    const std::string name = where + " \"" + key + "\"";
    if (!values.is_array() || values.size() != N) failJson(source, name, "is not an array of " + std::to_string(N) + " numbers");
    std::array<decltype(read(values[0], name)), N> result{};
    for (size_t k = 0; k < N; ++k) result[k] = read(values[k], name + "[" + std::to_string(k) + "]");
    return result;
}

MeshletBounds boundsFromJson(const Json& entry, const std::string& source, const std::string& where) {
    if (!entry.is_object()) failJson(source, where, "is not an object");
    auto real = [&](const Json& value, const std::string& at) { return finiteFloat(value, source, at); };
    auto signedByte = [&](const Json& value, const std::string& at) { return int8_t(wholeNumber(value, -128, 127, source, at)); };
    MeshletBounds bounds;
    bounds.center = fixedArray<3>(entry, "center", source, where, real);
    bounds.radius = real(member(entry, "radius", source, where), where + " \"radius\"");
    bounds.coneApex = fixedArray<3>(entry, "cone_apex", source, where, real);
    bounds.coneAxis = fixedArray<3>(entry, "cone_axis", source, where, real);
    bounds.coneCutoff = real(member(entry, "cone_cutoff", source, where), where + " \"cone_cutoff\"");
    bounds.coneAxisS8 = fixedArray<3>(entry, "cone_axis_s8", source, where, signedByte);
    bounds.coneCutoffS8 = signedByte(member(entry, "cone_cutoff_s8", source, where), where + " \"cone_cutoff_s8\"");
    return bounds;
}

// --- Binary ----------------------------------------------------------------------------------------

uint32_t u32At(const std::string& bytes, size_t offset) {
    uint32_t value = 0;
    for (int k = 3; k >= 0; --k) value = value << 8 | uint8_t(bytes[offset + k]);
    return value;
}

float f32At(const std::string& bytes, size_t offset) {
    const uint32_t bits = u32At(bytes, offset);
    float value = 0.0f;
    std::memcpy(&value, &bits, 4);
    return value;
}

void putU32(std::string& bytes, uint32_t value) {
    for (int k = 0; k < 4; ++k) bytes.push_back(char(value >> (8 * k) & 0xff));
}

void putF32(std::string& bytes, float value) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, 4);
    putU32(bytes, bits);
}

size_t paddedToFour(size_t count) { return (count + 3) & ~size_t(3); }
uint64_t paddedToEight(uint64_t count) { return (count + 7) & ~uint64_t(7); }

double f64At(const std::string& bytes, size_t offset) {
    const uint64_t bits = uint64_t(u32At(bytes, offset)) | uint64_t(u32At(bytes, offset + 4)) << 32;
    double value = 0.0;
    std::memcpy(&value, &bits, 8);
    return value;
}

void putF64(std::string& bytes, double value) {
    uint64_t bits = 0;
    std::memcpy(&bits, &value, 8);
    putU32(bytes, uint32_t(bits)), putU32(bytes, uint32_t(bits >> 32));
}

// The start both binary forms share: `magic`, a whole 32-byte header, version 1. A file without the
// magic is refused as not a `kind` file.
void checkBinaryHeader(const std::string& bytes, const std::string& source, const char* magic, const std::string& kind) {
    if (bytes.compare(0, 8, magic, 8) != 0)
        throw MeshletFileError(source + ": not a " + kind + " file: a binary one starts with the 8 bytes '" + std::string(magic, 8) +
                               "', this one with " + quotedForMessage(bytes.substr(0, 8)) + " (and a JSON one with '{')");
    if (bytes.size() < kHeaderBytes)
        throw MeshletFileError(source + ": truncated: the file ends at byte " + std::to_string(bytes.size()) + ", inside the 32-byte header");
    const uint32_t version = u32At(bytes, 8);
    if (version != 1) throw MeshletFileError(source + ": byte 8: version " + std::to_string(version) + ", this reader knows version 1");
}

// meshoptimizer's three arrays from byte 32, their sizes already checked against the file's; the
// byte after the triangles.
size_t binaryMeshletArrays(const std::string& bytes, uint64_t meshletCount, uint64_t vertexCount, uint64_t triangleBytes, MeshletArrays& arrays) {
    size_t at = kHeaderBytes;
    arrays.meshlets.resize(meshletCount);
    for (auto& meshlet : arrays.meshlets)
        for (uint32_t& field : meshlet) field = u32At(bytes, at), at += 4;
    arrays.vertices.resize(vertexCount);
    for (uint32_t& vertex : arrays.vertices) vertex = u32At(bytes, at), at += 4;
    arrays.triangles.assign(bytes.begin() + long(at), bytes.begin() + long(at + triangleBytes));
    return at + triangleBytes;
}

// The arrays as both binary forms lay them after the header, the triangles unpadded.
void putMeshletArrays(std::string& bytes, const MeshletArrays& arrays) {
    for (const auto& meshlet : arrays.meshlets)
        for (uint32_t field : meshlet) putU32(bytes, field);
    for (uint32_t vertex : arrays.vertices) putU32(bytes, vertex);
    bytes.append(arrays.triangles.begin(), arrays.triangles.end());
}

// Whether the bytes start, after white space, as a JSON object does.
bool startsAsJson(const std::string& bytes) {
    const size_t first = bytes.find_first_not_of(" \t\r\n");
    return first != std::string::npos && bytes[first] == '{';
}

}  // namespace

bool isMeshletFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string start(64, '\0');
    in.read(start.data(), std::streamsize(start.size()));
    start.resize(size_t(in.gcount()));
    if (startsAsJson(start) || lowerCaseExtension(path) == ".meshlets") return true;
    // Bytes no text has (an id file is text): a binary meshlet file, whatever its first 8 bytes say.
    return std::any_of(start.begin(), start.end(), [](char c) {
        const auto byte = uint8_t(c);
        return byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r' && byte != '\f' && byte != '\v';
    }) || start.compare(0, 8, kMagic, 8) == 0;
}

namespace {

// The document of a JSON file whose "format" is `format`.
Json jsonDocument(const std::string& text, const std::string& source, const char* format) {
    Json document;
    try {
        document = Json::parse(text);
    } catch (const Json::exception& error) {  // parse_error, and out_of_range for a number past a double
        throw MeshletFileError(source + ": not valid JSON (" + error.what() + ")");
    }
    if (!document.is_object()) failJson(source, "the document", "is not a JSON object");
    const Json& given = member(document, "format", source);
    if (!given.is_string() || given.get<std::string>() != format)
        failJson(source, "\"format\"", "is " + given.dump() + ", not \"" + format + "\"");
    return document;
}

// meshoptimizer's three arrays and the optional bounds, as a meshlet file and a hierarchy file hold them.
MeshletArrays meshletArraysOfJson(const Json& document, const std::string& source) {
    MeshletArrays arrays;
    const Json& meshlets = arrayMember(document, "meshlets", source);
    for (size_t m = 0; m < meshlets.size(); ++m) {
        const std::string where = "meshlets[" + std::to_string(m) + "]";
        if (!meshlets[m].is_array() || meshlets[m].size() != 4)
            failJson(source, where, "is not [vertex_offset, triangle_offset, vertex_count, triangle_count]");
        std::array<uint32_t, 4> meshlet{};
        for (int k = 0; k < 4; ++k)
            meshlet[k] = uint32_t(wholeNumber(meshlets[m][k], 0, std::numeric_limits<uint32_t>::max(), source, where + "[" + std::to_string(k) + "]"));
        arrays.meshlets.push_back(meshlet);
    }
    const Json& vertices = arrayMember(document, "meshlet_vertices", source);
    arrays.vertices.reserve(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i)
        arrays.vertices.push_back(
            uint32_t(wholeNumber(vertices[i], 0, std::numeric_limits<uint32_t>::max(), source, "meshlet_vertices[" + std::to_string(i) + "]")));
    const Json& triangles = arrayMember(document, "meshlet_triangles", source);
    arrays.triangles.reserve(triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i)
        arrays.triangles.push_back(uint8_t(wholeNumber(triangles[i], 0, 255, source, "meshlet_triangles[" + std::to_string(i) + "]")));
    if (document.contains("bounds")) {
        const Json& bounds = arrayMember(document, "bounds", source);
        if (bounds.size() != meshlets.size())
            failJson(source, "\"bounds\"", "has " + std::to_string(bounds.size()) + " entries for " + std::to_string(meshlets.size()) + " meshlets");
        for (size_t m = 0; m < bounds.size(); ++m) arrays.bounds.push_back(boundsFromJson(bounds[m], source, "bounds[" + std::to_string(m) + "]"));
    }
    return arrays;
}

}  // namespace

MeshletArrays parseMeshletJson(const std::string& text, const std::string& source) {
    return meshletArraysOfJson(jsonDocument(text, source, "meshoptimizer-meshlets"), source);
}

MeshletArrays parseMeshletBinary(const std::string& bytes, const std::string& source) {
    checkBinaryHeader(bytes, source, kMagic, "meshlet");
    const uint32_t flags = u32At(bytes, 12);
    if (flags > 1) throw MeshletFileError(source + ": byte 12: unknown flags " + std::to_string(flags) + " (only bit 0, bounds, is defined)");
    const uint64_t meshletCount = u32At(bytes, 16), vertexCount = u32At(bytes, 20), triangleBytes = u32At(bytes, 24);
    const bool hasBounds = flags & 1;
    const uint64_t expected = kHeaderBytes + meshletCount * kMeshletBytes + vertexCount * 4 + paddedToFour(triangleBytes) +
                              (hasBounds ? meshletCount * kBoundsBytes : 0);
    if (expected != bytes.size())
        throw MeshletFileError(source + ": the header promises " + std::to_string(meshletCount) + " meshlets, " + std::to_string(vertexCount) +
                               " meshlet_vertices and " + std::to_string(triangleBytes) + " triangle bytes" + (hasBounds ? " with bounds" : "") +
                               " (" + std::to_string(expected) + " bytes) but the file has " + std::to_string(bytes.size()));
    MeshletArrays arrays;
    size_t at = kHeaderBytes + paddedToFour(binaryMeshletArrays(bytes, meshletCount, vertexCount, triangleBytes, arrays) - kHeaderBytes);
    if (hasBounds) {
        arrays.bounds.resize(meshletCount);
        for (size_t m = 0; m < meshletCount; ++m, at += kBoundsBytes) {
            MeshletBounds& b = arrays.bounds[m];
            // 11 floats (centre, radius, apex, axis, cutoff), then the four signed bytes.
            float fields[11];
            for (int k = 0; k < 11; ++k) fields[k] = f32At(bytes, at + 4 * k);
            for (int k = 0; k < 11; ++k)
                if (!std::isfinite(fields[k]))
                    throw MeshletFileError(source + ": byte " + std::to_string(at + 4 * k) + ": bounds of meshlet " + std::to_string(m) +
                                           " hold a number that is not finite");
            b.center = {fields[0], fields[1], fields[2]};
            b.radius = fields[3];
            b.coneApex = {fields[4], fields[5], fields[6]};
            b.coneAxis = {fields[7], fields[8], fields[9]};
            b.coneCutoff = fields[10];
            for (int k = 0; k < 3; ++k) b.coneAxisS8[k] = int8_t(bytes[at + 44 + k]);
            b.coneCutoffS8 = int8_t(bytes[at + 47]);
        }
    }
    return arrays;
}

MeshletArrays readMeshletFile(const std::string& path) {
    std::string bytes;
    try {
        bytes = readFileBytes(path);
    } catch (const std::exception& error) {
        throw MeshletFileError(error.what());
    }
    if (startsAsJson(bytes)) return parseMeshletJson(bytes, path);
    return parseMeshletBinary(bytes, path);
}

// nlohmann's writer, in meshoptimizer's order: a float bound is written as the double it widens to,
// which reads back as the same float.
std::string meshletJson(const MeshletArrays& arrays) {
    nlohmann::ordered_json document = {{"format", "meshoptimizer-meshlets"},
                     {"meshlets", arrays.meshlets},
                     {"meshlet_vertices", arrays.vertices},
                     {"meshlet_triangles", arrays.triangles}};
    if (!arrays.bounds.empty()) {
        nlohmann::ordered_json& bounds = document["bounds"] = nlohmann::ordered_json::array();
        for (const MeshletBounds& b : arrays.bounds)
            bounds.push_back({{"center", b.center},
                              {"radius", b.radius},
                              {"cone_apex", b.coneApex},
                              {"cone_axis", b.coneAxis},
                              {"cone_cutoff", b.coneCutoff},
                              {"cone_axis_s8", b.coneAxisS8},
                              {"cone_cutoff_s8", b.coneCutoffS8}});
    }
    return document.dump() + "\n";
}

std::string meshletBinary(const MeshletArrays& arrays) {
    std::string bytes(kMagic, 8);
    for (uint64_t value : {uint64_t(1), uint64_t(arrays.bounds.empty() ? 0 : 1), uint64_t(arrays.meshlets.size()),
                           uint64_t(arrays.vertices.size()), uint64_t(arrays.triangles.size()), uint64_t(0)})
        putU32(bytes, uint32_t(value));
    putMeshletArrays(bytes, arrays);
    bytes.resize(bytes.size() + paddedToFour(arrays.triangles.size()) - arrays.triangles.size(), '\0');
    for (const MeshletBounds& b : arrays.bounds) {
        for (float value : b.center) putF32(bytes, value);
        putF32(bytes, b.radius);
        for (float value : b.coneApex) putF32(bytes, value);
        for (float value : b.coneAxis) putF32(bytes, value);
        putF32(bytes, b.coneCutoff);
        for (int8_t value : b.coneAxisS8) bytes.push_back(char(value));
        bytes.push_back(char(b.coneCutoffS8));
    }
    return bytes;
}

namespace {

// A finite number kept as the double it was written as (errors and spheres round-trip exactly).
double finiteDouble(const Json& value, const std::string& source, const std::string& where) {
    if (!value.is_number() || !std::isfinite(value.get<double>())) failJson(source, where, "is not a finite number");
    return value.get<double>();
}

// A sphere and an error as a hierarchy file holds them, and the level.
template <typename Record>
Record boundRecord(const Json& entry, const std::string& source, const std::string& where, uint32_t levels) {
    if (!entry.is_object()) failJson(source, where, "is not an object");
    Record record;
    record.level = uint32_t(wholeNumber(member(entry, "level", source, where), 0, levels, source, where + " \"level\""));
    const auto center = fixedArray<3>(entry, "center", source, where, [&](const Json& value, const std::string& at) { return finiteDouble(value, source, at); });
    record.sphere = {glm::dvec3(center[0], center[1], center[2]), finiteDouble(member(entry, "radius", source, where), source, where + " \"radius\"")};
    record.error = finiteDouble(member(entry, "error", source, where), source, where + " \"error\"");
    return record;
}

}  // namespace

HierarchyRecords parseHierarchyJson(const std::string& text, const std::string& source) {
    const Json document = jsonDocument(text, source, "conescope-cluster-lod");
    const int64_t version = wholeNumber(member(document, "version", source), 0, std::numeric_limits<int32_t>::max(), source, "\"version\"");
    if (version != 1) failJson(source, "\"version\"", std::to_string(version) + ", this reader knows version 1");
    HierarchyRecords records;
    records.arrays = meshletArraysOfJson(document, source);
    const Json& clusters = arrayMember(document, "clusters", source);
    const Json& groups = arrayMember(document, "groups", source);
    const uint32_t most = uint32_t(std::min<size_t>(clusters.size(), std::numeric_limits<uint32_t>::max()));
    for (size_t g = 0; g < groups.size(); ++g) records.groups.push_back(boundRecord<HierarchyGroupRecord>(groups[g], source, "groups[" + std::to_string(g) + "]", most));
    for (size_t m = 0; m < clusters.size(); ++m) {
        const std::string where = "clusters[" + std::to_string(m) + "]";
        HierarchyClusterRecord record = boundRecord<HierarchyClusterRecord>(clusters[m], source, where, most);
        const int64_t groupCount = int64_t(groups.size());
        record.group = wholeNumber(member(clusters[m], "group", source, where), -1, groupCount - 1, source, where + " \"group\"");
        record.refined = wholeNumber(member(clusters[m], "refined", source, where), -1, groupCount - 1, source, where + " \"refined\"");
        records.clusters.push_back(record);
    }
    return records;
}

namespace {

// A hierarchy binary's fault: the path, the byte offset, who (a cluster or group, when one) and what.
[[noreturn]] void failBinary(const std::string& source, size_t offset, const std::string& what) {
    throw MeshletFileError(source + ": byte " + std::to_string(offset) + ": " + what);
}

// A sphere and an error at `at` (five doubles), each finite and the radius and error 0 or more.
template <typename Record>
void readBound(const std::string& bytes, size_t at, const std::string& source, const std::string& who, Record& record) {
    double fields[5];
    for (int k = 0; k < 5; ++k) {
        fields[k] = f64At(bytes, at + 8 * k);
        if (!std::isfinite(fields[k])) failBinary(source, at + 8 * k, who + ": " + (k < 3 ? "its centre" : k == 3 ? "its radius" : "its error") + " is not a finite number");
    }
    record.sphere = {glm::dvec3(fields[0], fields[1], fields[2]), fields[3]};
    record.error = fields[4];
}

}  // namespace

HierarchyRecords parseHierarchyBinary(const std::string& bytes, const std::string& source) {
    checkBinaryHeader(bytes, source, kHierarchyMagic, "hierarchy");
    const uint32_t flags = u32At(bytes, 12);
    if (flags != 0) failBinary(source, 12, "flags " + std::to_string(flags) + ", none are defined (0)");
    const uint64_t clusterCount = u32At(bytes, 16), vertexCount = u32At(bytes, 20), triangleBytes = u32At(bytes, 24), groupCount = u32At(bytes, 28);
    const uint64_t recordsAt = paddedToEight(kHeaderBytes + clusterCount * kMeshletBytes + vertexCount * 4 + triangleBytes);
    const uint64_t expected = recordsAt + clusterCount * kClusterRecordBytes + groupCount * kGroupRecordBytes;
    if (expected != bytes.size())
        throw MeshletFileError(source + ": " + (bytes.size() < expected ? "truncated: " : "") + "the header promises " + std::to_string(clusterCount) +
                               " clusters, " + std::to_string(vertexCount) + " meshlet_vertices, " + std::to_string(triangleBytes) +
                               " triangle bytes and " + std::to_string(groupCount) + " groups (" + std::to_string(expected) +
                               " bytes) but the file has " + std::to_string(bytes.size()));
    HierarchyRecords records;
    size_t at = binaryMeshletArrays(bytes, clusterCount, vertexCount, triangleBytes, records.arrays);
    for (; at < recordsAt; ++at)
        if (bytes[at] != 0) failBinary(source, at, "padding after meshlet_triangles is not zero");
    const auto level = [&](size_t offset, const std::string& who) {
        const uint32_t value = u32At(bytes, offset);
        if (value > clusterCount) failBinary(source, offset, who + ": level " + std::to_string(value) + " is above the cluster count " + std::to_string(clusterCount));
        return value;
    };
    const auto groupIndex = [&](size_t offset, const std::string& who, const char* what) {
        const int64_t value = int32_t(u32At(bytes, offset));
        if (value < -1 || value >= int64_t(groupCount))
            failBinary(source, offset, who + ": " + what + " " + std::to_string(value) + " is not a group (-1 or below " + std::to_string(groupCount) + ")");
        return value;
    };
    records.clusters.resize(clusterCount);
    for (size_t m = 0; m < clusterCount; ++m, at += kClusterRecordBytes) {
        const std::string who = "cluster " + std::to_string(m);
        HierarchyClusterRecord& record = records.clusters[m];
        record.level = level(at, who);
        record.group = groupIndex(at + 4, who, "group");
        record.refined = groupIndex(at + 8, who, "refined group");
        if (u32At(bytes, at + 12) != 0) failBinary(source, at + 12, who + ": its reserved field is not 0");
        readBound(bytes, at + 16, source, who, record);
    }
    records.groups.resize(groupCount);
    for (size_t g = 0; g < groupCount; ++g, at += kGroupRecordBytes) {
        const std::string who = "group " + std::to_string(g);
        records.groups[g].level = level(at, who);
        if (u32At(bytes, at + 4) != 0) failBinary(source, at + 4, who + ": its reserved field is not 0");
        readBound(bytes, at + 8, source, who, records.groups[g]);
    }
    return records;
}

std::string hierarchyBinary(const HierarchyRecords& records) {
    const MeshletArrays& arrays = records.arrays;
    std::string bytes(kHierarchyMagic, 8);
    for (size_t value : {size_t(1), size_t(0), arrays.meshlets.size(), arrays.vertices.size(), arrays.triangles.size(), records.groups.size()})
        putU32(bytes, uint32_t(value));
    putMeshletArrays(bytes, arrays);
    bytes.resize(paddedToEight(bytes.size()), '\0');
    const auto putBound = [&](const Sphere& sphere, double error) {
        for (double value : {sphere.center.x, sphere.center.y, sphere.center.z, sphere.radius, error}) putF64(bytes, value);
    };
    for (const HierarchyClusterRecord& c : records.clusters) {
        for (int64_t value : {int64_t(c.level), c.group, c.refined, int64_t(0)}) putU32(bytes, uint32_t(value));
        putBound(c.sphere, c.error);
    }
    for (const HierarchyGroupRecord& g : records.groups) {
        putU32(bytes, g.level), putU32(bytes, 0);
        putBound(g.sphere, g.error);
    }
    return bytes;
}

HierarchyRecords readHierarchyFile(const std::string& path) {
    std::string bytes;
    try {
        bytes = readFileBytes(path);
    } catch (const std::exception& error) {
        throw MeshletFileError(error.what());
    }
    if (startsAsJson(bytes)) return parseHierarchyJson(bytes, path);
    return parseHierarchyBinary(bytes, path);
}

bool isHierarchyBinaryPath(const std::string& path) {
    const std::string extension = lowerCaseExtension(path);
    return extension == ".lod" || extension == ".bin";
}

std::string hierarchyJson(const HierarchyRecords& records) {
    nlohmann::ordered_json document = {{"format", "conescope-cluster-lod"},
                                       {"version", 1},
                                       {"meshlets", records.arrays.meshlets},
                                       {"meshlet_vertices", records.arrays.vertices},
                                       {"meshlet_triangles", records.arrays.triangles}};
    const auto bound = [](uint32_t level, const Sphere& sphere, double error) {
        return nlohmann::ordered_json{{"level", level}, {"center", {sphere.center.x, sphere.center.y, sphere.center.z}}, {"radius", sphere.radius}, {"error", error}};
    };
    nlohmann::ordered_json& clusters = document["clusters"] = nlohmann::ordered_json::array();
    for (const HierarchyClusterRecord& c : records.clusters) {
        nlohmann::ordered_json entry = bound(c.level, c.sphere, c.error);
        entry["group"] = c.group, entry["refined"] = c.refined;
        clusters.push_back(entry);
    }
    nlohmann::ordered_json& groups = document["groups"] = nlohmann::ordered_json::array();
    for (const HierarchyGroupRecord& g : records.groups) groups.push_back(bound(g.level, g.sphere, g.error));
    return document.dump() + "\n";
}

}  // namespace conescope
