// readVtpXml: the element tree of a .vtp file through expat, with each element's place in the
// file's bytes, and the checks that what VTK reads from those bytes is what the XML says.
#include "io/VtpXml.h"

#include <algorithm>
#include <exception>

#include <expat.h>

#include "io/MeshReader.h"

namespace conescope {

namespace {

constexpr std::string_view appendedDataPattern = "<AppendedData";

size_t lineAt(std::string_view bytes, size_t position) {
    return 1 + static_cast<size_t>(std::count(bytes.begin(), bytes.begin() + std::min(position, bytes.size()), '\n'));
}

// A byte order mark or a '<' of two bytes. expat decodes UTF-16, but VTK reads the data and we
// patch the text byte by byte.
bool looksLikeUtf16(std::string_view bytes) {
    std::string_view first = bytes.substr(0, 2);
    return first == "\xfe\xff" || first == "\xff\xfe" || first == std::string_view("<\0", 2) || first == std::string_view("\0<", 2);
}

// The parse in progress. Handlers must not throw through expat's C frames: the first problem (or
// exception, such as bad_alloc) is kept here, the parser stopped, and readVtpXml throws it afterwards.
struct ExpatWalk {
    XML_Parser parser = nullptr;
    std::string_view bytes;
    VtpXml xml;
    std::vector<size_t> open;  // indices of the elements not yet closed, outermost first
    std::optional<std::pair<size_t, std::string>> problem;  // line, what
    std::exception_ptr exception;
    bool stopped = false;  // expat still reports the end of a self-closed tag it was stopped in
};

void stop(ExpatWalk& walk) {
    walk.stopped = true;
    XML_StopParser(walk.parser, XML_FALSE);
}

void stopWithProblem(ExpatWalk& walk, size_t line, const std::string& what) {
    walk.problem = std::make_pair(line, what);
    stop(walk);
}

// The start tag as the file holds it; what VTK sees of it when it seeks data by byte position.
// Empty when expat's position is not a tag of the file (an element from an entity's text).
std::string_view rawStartTag(const ExpatWalk& walk) {
    XML_Index begin = XML_GetCurrentByteIndex(walk.parser);
    int length = XML_GetCurrentByteCount(walk.parser);
    if (begin < 0 || length < 2 || static_cast<size_t>(begin) + static_cast<size_t>(length) > walk.bytes.size()) return {};
    std::string_view tag = walk.bytes.substr(static_cast<size_t>(begin), static_cast<size_t>(length));
    return tag.front() == '<' && tag.back() == '>' ? tag : std::string_view();
}

// vtkXMLDataParser finds where a DataArray's or AppendedData's data start by the first '>' after
// the tag's '<'; a '>' in an attribute value (legal XML) would make it read the tag as data.
bool vtkFindsTagEnd(std::string_view tag, const std::string& name) {
    if (name != "DataArray" && name != "AppendedData") return true;
    return tag.find('>') == tag.size() - 1;
}

std::string tagProblem(std::string_view tag, const std::string& name) {
    if (tag.empty())
        return "element <" + name + "> is written by an entity reference; VTK finds an element's data by its place in the file, "
               "so elements must stand in the file as they are";
    if (!vtkFindsTagEnd(tag, name))
        return "an attribute value of this <" + name + "> holds '>', which VTK takes for the end of the tag "
               "(it would read the rest of the tag as data); write it as &gt;";
    return {};
}

void addAttributes(VtpElement& element, const XML_Char** attributes) {
    for (size_t a = 0; attributes[a] && attributes[a + 1]; a += 2) element.attributes.emplace_back(attributes[a], attributes[a + 1]);
}

// VTK closes the document itself after <AppendedData ...> ("/></VTKFile>"), which only works
// when it stands directly in the root.
std::string appendedDataPlaceProblem(const ExpatWalk& walk) {
    if (walk.open.size() == 1) return {};
    if (walk.open.empty()) return "<AppendedData> is the root element; it must stand inside <VTKFile>";
    return "<AppendedData> stands inside <" + walk.xml.elements[walk.open.back()].name +
           ">; VTK reads it only as a child of the root <VTKFile>";
}

void startElement(ExpatWalk& walk, const XML_Char* name, const XML_Char** attributes) {
    VtpElement element;
    element.name = name;
    element.line = static_cast<size_t>(XML_GetCurrentLineNumber(walk.parser));
    std::string_view tag = rawStartTag(walk);
    if (std::string problem = tagProblem(tag, element.name); !problem.empty()) return stopWithProblem(walk, element.line, problem);
    element.tagBegin = static_cast<size_t>(tag.data() - walk.bytes.data());
    element.tagEnd = element.tagBegin + tag.size();
    element.selfClosed = tag.size() >= 3 && tag[tag.size() - 2] == '/';
    element.parent = walk.open.empty() ? noElement : walk.open.back();
    addAttributes(element, attributes);
    walk.xml.elements.push_back(std::move(element));
    if (walk.xml.elements.back().name == "AppendedData") {
        // The bytes after this tag may be raw binary: the XML ends here, as it does for VTK.
        walk.xml.appendedData = walk.xml.elements.size() - 1;
        if (std::string problem = appendedDataPlaceProblem(walk); !problem.empty())
            return stopWithProblem(walk, walk.xml.elements.back().line, problem);
        return stop(walk);
    }
    walk.open.push_back(walk.xml.elements.size() - 1);
}

void endElement(ExpatWalk& walk) {
    if (walk.stopped || walk.open.empty()) return;
    VtpElement& element = walk.xml.elements[walk.open.back()];
    walk.open.pop_back();
    element.contentEnd = element.selfClosed ? element.tagEnd : static_cast<size_t>(XML_GetCurrentByteIndex(walk.parser));
}

void onStartElement(void* data, const XML_Char* name, const XML_Char** attributes) {
    ExpatWalk& walk = *static_cast<ExpatWalk*>(data);
    try {
        startElement(walk, name, attributes);
    } catch (...) {
        walk.exception = std::current_exception();
        stop(walk);
    }
}

void onEndElement(void* data, const XML_Char*) { endElement(*static_cast<ExpatWalk*>(data)); }

// Errors that mean the XML stopped before it was complete.
bool endsEarly(XML_Error error) {
    return error == XML_ERROR_NO_ELEMENTS || error == XML_ERROR_UNCLOSED_TOKEN || error == XML_ERROR_PARTIAL_CHAR ||
           error == XML_ERROR_UNCLOSED_CDATA_SECTION;
}

std::string expatErrorMessage(XML_Parser parser) {
    XML_Error error = XML_GetErrorCode(parser);
    std::string message = std::string("malformed XML: ") + XML_ErrorString(error) + " (column " +
                          std::to_string(XML_GetCurrentColumnNumber(parser) + 1) + ")";
    return endsEarly(error) ? message + "; the file ends before the XML does (cut short?)" : message;
}

// Feeds the bytes in pieces expat's int length can hold; false once expat stops.
bool parseAll(XML_Parser parser, std::string_view bytes) {
    constexpr size_t piece = size_t(1) << 30;
    for (size_t position = 0;; position += piece) {
        size_t length = std::min(piece, bytes.size() - position);
        bool last = position + length == bytes.size();
        if (XML_Parse(parser, bytes.data() + position, static_cast<int>(length), last) != XML_STATUS_OK) return false;
        if (last) return true;
    }
}

[[noreturn]] void failAtLine(const std::string& path, size_t line, const std::string& what) {
    throw MeshReadError(path + ":" + std::to_string(line) + ": " + what);
}

// vtkXMLDataParser stops its XML at the first "<AppendedData" in the bytes, wherever it stands.
void requireAppendedDataPatternAtElement(const std::string& path, std::string_view bytes, const VtpXml& xml, size_t parsedUpTo) {
    size_t first = bytes.find(appendedDataPattern);
    size_t element = xml.appendedData == noElement ? std::string_view::npos : xml.elements[xml.appendedData].tagBegin;
    if (first == std::string_view::npos || first == element || first >= parsedUpTo) return;
    failAtLine(path, lineAt(bytes, first),
               "\"<AppendedData\" outside an <AppendedData> tag (in a comment, CDATA, text or another name); "
               "VTK ends the XML at the first one it meets");
}

struct ExpatParser {
    XML_Parser parser = XML_ParserCreate(nullptr);
    ~ExpatParser() { XML_ParserFree(parser); }
};

}  // namespace

std::optional<std::string_view> VtpElement::attribute(std::string_view key) const {
    for (const auto& [name, value] : attributes)
        if (name == key) return std::string_view(value);
    return std::nullopt;
}

VtpXml readVtpXml(const std::string& path, std::string_view bytes) {
    if (looksLikeUtf16(bytes)) throw MeshReadError(path + ": UTF-16 text; VTK reads .vtp files as UTF-8 (or another ASCII-compatible encoding)");
    ExpatParser expat;
    if (!expat.parser) throw MeshReadError(path + ": cannot create an XML parser (out of memory)");
    ExpatWalk walk;
    walk.parser = expat.parser;
    walk.bytes = bytes;
    XML_SetUserData(expat.parser, &walk);
    XML_SetElementHandler(expat.parser, onStartElement, onEndElement);
    bool complete = parseAll(expat.parser, bytes);
    size_t parsedUpTo = complete ? bytes.size() : static_cast<size_t>(std::max<XML_Index>(0, XML_GetCurrentByteIndex(expat.parser)));
    if (walk.exception) std::rethrow_exception(walk.exception);
    requireAppendedDataPatternAtElement(path, bytes, walk.xml, parsedUpTo);
    if (walk.problem) failAtLine(path, walk.problem->first, walk.problem->second);
    if (!complete && walk.xml.appendedData == noElement)
        failAtLine(path, static_cast<size_t>(XML_GetCurrentLineNumber(expat.parser)), expatErrorMessage(expat.parser));
    return std::move(walk.xml);
}

bool isVtkSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view textVtkReadsAfterTag(std::string_view bytes, const VtpElement& element) {
    std::string_view after = bytes.substr(element.tagEnd);
    return after.substr(0, after.find_first_of("<&"));
}

std::string_view contentBytes(std::string_view bytes, const VtpElement& element) {
    if (element.selfClosed || element.contentEnd == std::string::npos) return {};
    return bytes.substr(element.tagEnd, element.contentEnd - element.tagEnd);
}

std::optional<std::string_view> appendedDataBytes(std::string_view bytes, const VtpElement& appendedData) {
    size_t marker = appendedData.tagEnd;
    while (marker < bytes.size() && isVtkSpace(bytes[marker])) ++marker;
    if (marker >= bytes.size() || bytes[marker] != '_') return std::nullopt;  // VTK would read from here with a warning
    size_t begin = marker + 1;
    size_t endTag = bytes.rfind("</AppendedData>");
    size_t end = endTag != std::string_view::npos && endTag > begin ? endTag : bytes.size();
    return bytes.substr(begin, end - begin);
}

}  // namespace conescope
