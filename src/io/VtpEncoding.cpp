// The encodings of .vtp arrays, decoded as far as the checks in VtpCheck.cpp need them.
#include "io/VtpEncoding.h"

#include <charconv>
#include <limits>
#include <vector>

#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkZLibDataCompressor.h>

#include "io/MeshReader.h"
#include "io/TextScanning.h"

namespace conescope {

namespace {

// Unsigned integer of `size` bytes at position (the caller checked the bytes are there).
uint64_t unsignedAt(std::string_view bytes, size_t position, size_t size, bool bigEndian) {
    uint64_t value = 0;
    for (size_t k = 0; k < size; ++k) {
        size_t byteIndex = bigEndian ? k : size - 1 - k;
        value = (value << 8) | static_cast<unsigned char>(bytes[position + byteIndex]);
    }
    return value;
}

// Value of a base64 character as vtkBase64Utilities decodes it ('=' pads count as 0), or -1.
int base64Digit(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return c == '=' ? 0 : -1;
}

// The decompressor vtkXMLReader uses for a compressor attribute, or null for one it does not know.
vtkSmartPointer<vtkDataCompressor> compressorNamed(std::string_view name) {
    if (name == "vtkZLibDataCompressor") return vtkSmartPointer<vtkZLibDataCompressor>::New();
    if (name == "vtkLZ4DataCompressor") return vtkSmartPointer<vtkLZ4DataCompressor>::New();
    if (name == "vtkLZMADataCompressor") return vtkSmartPointer<vtkLZMADataCompressor>::New();
    return nullptr;
}

[[noreturn]] void corrupt(const std::string& where, const std::string& what) { throw MeshReadError(where + " is corrupt: " + what); }

uint64_t headerWord(const BinaryLayout& layout, const std::string& header, size_t word) {
    return unsignedAt(header, word * layout.wordSize, layout.wordSize, layout.bigEndian);
}

// An integer value of the array's type that is not negative (VTK rejects negative offsets itself).
std::optional<uint64_t> nonNegativeValue(const BinaryLayout& layout, const std::string& bytes, size_t position, std::string_view type) {
    uint64_t size = typeSize(type);
    uint64_t raw = unsignedAt(bytes, position, size, layout.bigEndian);
    bool isSigned = type.rfind("Int", 0) == 0;
    if (isSigned && (raw >> (8 * size - 1)) & 1) return std::nullopt;
    return raw;
}

void checkWholeValues(const std::string& where, uint64_t bytes, std::string_view type) {
    if (bytes % typeSize(type) != 0)
        corrupt(where, std::to_string(bytes) + " bytes are not a whole number of " + std::string(type) + " values");
}

StoredValues uncompressedValues(const BinaryLayout& layout, const EncodedBytes& data, const std::string& where, std::string_view type,
                                std::optional<uint64_t> wanted) {
    const size_t word = layout.wordSize;
    uint64_t valueSize = typeSize(type);
    std::optional<std::string> header = data.read(word);
    if (!header) corrupt(where, "its header runs past the end of the data");
    uint64_t byteCount = headerWord(layout, *header, 0);
    if (byteCount > data.capacity() - word) corrupt(where, "byte count " + std::to_string(byteCount) + " runs past the end of the data");
    checkWholeValues(where, byteCount, type);
    StoredValues stored{byteCount / valueSize, true, std::nullopt};
    if (wanted && *wanted < stored.values)
        if (std::optional<std::string> bytes = data.read(word + (*wanted + 1) * valueSize))
            stored.wantedValue = nonNegativeValue(layout, *bytes, word + *wanted * valueSize, type);
    return stored;
}

// A compressed array's block table, checked against the data that is there.
struct CompressedBlocks {
    EncodedBytes data;  // the compressed blocks, one after the other
    uint64_t blockSize = 0, lastBlockSize = 0;
    std::vector<uint64_t> starts;  // where each block starts in `data`, and where the last ends
    uint64_t blockCount() const { return starts.size() - 1; }
    uint64_t plainBytes(uint64_t block) const { return block + 1 < blockCount() || lastBlockSize == 0 ? blockSize : lastBlockSize; }
    uint64_t totalPlainBytes() const { return blockCount() == 0 ? 0 : (blockCount() - 1) * blockSize + plainBytes(blockCount() - 1); }
};

// VTK allocates the block size table from the block count and each block from its sizes, so all
// must fit the data in the file before VTK sees them.
CompressedBlocks compressedBlocks(const BinaryLayout& layout, const EncodedBytes& data, const std::string& where) {
    const size_t word = layout.wordSize;
    std::optional<std::string> table = data.read(3 * word);
    if (!table) corrupt(where, "block table runs past the end of the data");
    uint64_t blockCount = headerWord(layout, *table, 0);
    if (blockCount > (data.capacity() - 3 * word) / word) corrupt(where, "block table runs past the end of the data");
    CompressedBlocks blocks{data.after((3 + blockCount) * word), headerWord(layout, *table, 1), headerWord(layout, *table, 2), {0}};
    if (blockCount > 0 && (blocks.blockSize == 0 || blocks.lastBlockSize > blocks.blockSize)) corrupt(where, "inconsistent block sizes");
    if (blockCount == 0 && blocks.lastBlockSize != 0) corrupt(where, "inconsistent block sizes");
    if (blockCount > 1 && blocks.blockSize > std::numeric_limits<uint64_t>::max() / blockCount) corrupt(where, "inconsistent block sizes");
    std::optional<std::string> header = data.read((3 + blockCount) * word);
    if (!header) corrupt(where, "block table runs past the end of the data");
    for (uint64_t block = 0; block < blockCount; ++block) {
        uint64_t size = headerWord(layout, *header, 3 + block);
        if (size > blocks.data.capacity() - blocks.starts.back()) corrupt(where, "compressed blocks run past the end of the data");
        blocks.starts.push_back(blocks.starts.back() + size);
    }
    return blocks;
}

// Bytes [begin, begin + count) of a compressed array, decompressing only the blocks holding them;
// nothing when a block does not decompress (VTK then reports the damage).
std::optional<std::string> decompressedRange(vtkDataCompressor& decompressor, const CompressedBlocks& blocks, uint64_t begin, uint64_t count) {
    std::string range;
    for (uint64_t block = begin / blocks.blockSize; range.size() < count; ++block) {
        std::optional<std::string> compressed = blocks.data.read(blocks.starts[block + 1]);
        if (!compressed) return std::nullopt;
        std::string plain(blocks.plainBytes(block), '\0');
        const auto* source = reinterpret_cast<const unsigned char*>(compressed->data()) + blocks.starts[block];
        size_t sourceSize = blocks.starts[block + 1] - blocks.starts[block];
        if (decompressor.Uncompress(source, sourceSize, reinterpret_cast<unsigned char*>(plain.data()), plain.size()) != plain.size())
            return std::nullopt;
        uint64_t from = range.empty() ? begin - block * blocks.blockSize : 0;
        range += plain.substr(from, count - range.size());
    }
    return range;
}

StoredValues compressedValues(const BinaryLayout& layout, const EncodedBytes& data, const std::string& where, std::string_view type,
                              std::optional<uint64_t> wanted) {
    CompressedBlocks blocks = compressedBlocks(layout, data, where);
    checkWholeValues(where, blocks.totalPlainBytes(), type);
    uint64_t valueSize = typeSize(type);
    StoredValues stored{blocks.totalPlainBytes() / valueSize, true, std::nullopt};
    if (wanted && *wanted < stored.values && layout.decompressor)
        if (std::optional<std::string> bytes = decompressedRange(*layout.decompressor, blocks, *wanted * valueSize, valueSize))
            stored.wantedValue = nonNegativeValue(layout, *bytes, 0, type);
    return stored;
}

}  // namespace

bool isVtkXmlType(std::string_view type) {
    for (const char* known : {"Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64", "Float32", "Float64", "String", "Bit"})
        if (type == known) return true;
    return false;
}

uint64_t typeSize(std::string_view type) {
    if (type == "Int8" || type == "UInt8") return 1;
    if (type == "Int16" || type == "UInt16") return 2;
    if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
    if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
    return 0;
}

bool isIntegerType(std::string_view type) { return type.find("Int") != std::string_view::npos; }

BinaryLayout binaryLayout(std::optional<std::string_view> headerType, std::optional<std::string_view> byteOrder,
                          std::optional<std::string_view> compressor) {
    BinaryLayout layout;
    layout.wordSize = headerType == std::optional<std::string_view>("UInt64") ? 8 : 4;
    layout.bigEndian = byteOrder == std::optional<std::string_view>("BigEndian");
    layout.compressed = compressor.has_value();
    if (compressor) layout.decompressor = compressorNamed(*compressor);
    return layout;
}

// Base64 is decoded like vtkBase64InputStream: four characters at a time, a character outside the
// alphabet or a group with a '=' pad ending the stream.
std::optional<std::string> EncodedBytes::read(uint64_t count) const {
    if (count > capacity()) return std::nullopt;
    if (!base64_) return std::string(text_.substr(0, count));
    std::string bytes;
    for (size_t group = 0; bytes.size() < count; group += 4) {
        std::string_view characters = text_.substr(group, 4);
        uint32_t bits = 0;
        for (char c : characters) {
            if (base64Digit(c) < 0) return std::nullopt;
            bits = (bits << 6) | static_cast<uint32_t>(base64Digit(c));
        }
        size_t decoded = characters[2] == '=' ? 1 : characters[3] == '=' ? 2 : 3;
        for (size_t k = 0; k < decoded && bytes.size() < count; ++k) bytes += static_cast<char>(bits >> (16 - 8 * k));
        if (decoded < 3 && bytes.size() < count) return std::nullopt;
    }
    return bytes;
}

EncodedBytes EncodedBytes::after(uint64_t count) const {
    size_t used = static_cast<size_t>(base64_ ? (count + 2) / 3 * 4 : count);
    return EncodedBytes(text_.substr(std::min(used, text_.size())), base64_);
}

namespace {

// A word as VTK's ASCII reader reads an integer from it (stream extraction): an optional sign and
// the digits that follow, whatever comes after them ("429496729junk" is 429496729; the next read
// then fails, but this one stands). Too large: the largest value, as the stream gives; negative or
// no digits: nothing.
std::optional<uint64_t> integerAsVtkReadsIt(std::string_view word) {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    size_t digits = 0;
    while (digits < word.size() && word[digits] >= '0' && word[digits] <= '9') ++digits;
    if (digits == 0) return std::nullopt;
    uint64_t value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + digits, value);
    if (error == std::errc::result_out_of_range) return std::numeric_limits<uint64_t>::max();
    return end == word.data() + digits ? std::optional<uint64_t>(value) : std::nullopt;
}

}  // namespace

StoredValues asciiValues(std::string_view text, std::optional<uint64_t> wanted) {
    StoredValues stored;
    std::string_view wantedWord;
    text::LineCursor lines(text, 0, 0);
    while (!lines.atEnd())
        for (std::string_view word : text::splitWords(lines.next())) {
            if (wanted && stored.values == *wanted) wantedWord = word;
            ++stored.values;
        }
    stored.wantedValue = integerAsVtkReadsIt(wantedWord);
    return stored;
}

StoredValues binaryValues(const BinaryLayout& layout, const EncodedBytes& data, const std::string& where, std::string_view type,
                          std::optional<uint64_t> wanted) {
    return layout.compressed ? compressedValues(layout, data, where, type, wanted) : uncompressedValues(layout, data, where, type, wanted);
}

}  // namespace conescope
