// How a .vtp array stores its values (internal to conescope_io): the VTK XML value types, ASCII
// words, and binary data (inline base64, raw or base64 appended, compressed or not) read as
// vtkXMLDataParser reads them, checking every size it would allocate from against the data there.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <vtkDataCompressor.h>
#include <vtkSmartPointer.h>

namespace conescope {

bool isVtkXmlType(std::string_view type);

// Bytes per value of an array type; 0 for String and Bit, which have no fixed size.
uint64_t typeSize(std::string_view type);

bool isIntegerType(std::string_view type);

// Binary data of every array (inline or appended) starts with a header of UInt32 or UInt64 words
// in the file's byte order: its byte count, or (compressed) its block count, block size, last
// block size and compressed block sizes. The root element's attributes give the layout.
struct BinaryLayout {
    size_t wordSize = 4;
    bool bigEndian = false;
    bool compressed = false;
    vtkSmartPointer<vtkDataCompressor> decompressor;  // null for a compressor VTK does not know (it refuses the file itself)
};

BinaryLayout binaryLayout(std::optional<std::string_view> headerType, std::optional<std::string_view> byteOrder,
                          std::optional<std::string_view> compressor);

// One array's binary data from where its header starts: raw bytes (appended, encoding="raw") or
// base64 text (format="binary", or appended with encoding="base64"), read as VTK reads them.
class EncodedBytes {
public:
    EncodedBytes(std::string_view text, bool base64) : text_(text), base64_(base64) {}

    // The most bytes the text can hold: a size read from the file is checked against this before
    // anything is allocated from it.
    uint64_t capacity() const { return base64_ ? text_.size() / 4 * 3 : text_.size(); }

    // The first `count` bytes, or nothing when the data end first.
    std::optional<std::string> read(uint64_t count) const;

    // The data after the first `count` bytes (at most capacity()), as a stream of its own: VTK
    // reads a compressed array's blocks as a new base64 stream starting after its header's text.
    EncodedBytes after(uint64_t count) const;

private:
    std::string_view text_;
    bool base64_;
};

// What the values of an array hold, as far as its encoding tells.
struct StoredValues {
    uint64_t values = 0;
    bool exact = false;                   // binary: the header gives the number exactly
    std::optional<uint64_t> wantedValue;  // the value asked for, when decodable and not negative
};

// An ASCII array's words, and word number `wanted` as an unsigned integer, read as VTK reads it
// (its leading digits, so that a forged "429496729junk" counts as the 429496729 VTK allocates for).
StoredValues asciiValues(std::string_view text, std::optional<uint64_t> wanted);

// A binary array of a fixed-size `type`: the values its header gives, and value number `wanted`
// decoded (decompressing only the block holding it). Throws MeshReadError "<where> is corrupt: ..."
// for a header or block table that runs past the data, or a size that is no whole number of values.
StoredValues binaryValues(const BinaryLayout& layout, const EncodedBytes& data, const std::string& where, std::string_view type,
                          std::optional<uint64_t> wanted);

}  // namespace conescope
