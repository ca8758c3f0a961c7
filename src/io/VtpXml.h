// The XML part of a .vtp file, read with expat as vtkXMLDataParser reads it (internal to
// conescope_io). VTK takes the element tree from expat but reads each array's data from the file's
// bytes after the start tag, so every element keeps where it stands in those bytes too.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace conescope {

constexpr size_t noElement = static_cast<size_t>(-1);

struct VtpElement {
    std::string name;
    std::vector<std::pair<std::string, std::string>> attributes;  // as expat decodes them
    size_t line = 0;                   // 1-based line of the start tag
    size_t tagBegin = 0;               // byte of the start tag's '<'
    size_t tagEnd = 0;                 // byte just after its '>'
    size_t contentEnd = std::string::npos;  // byte where the end tag starts (tagEnd when self-closed); npos if never closed
    bool selfClosed = false;           // written <name .../>
    size_t parent = noElement;         // index of the enclosing element, noElement for the root

    std::optional<std::string_view> attribute(std::string_view key) const;
};

struct VtpXml {
    std::vector<VtpElement> elements;  // in document order, so an element's descendants follow it
    size_t appendedData = noElement;   // index of <AppendedData>, whose start tag ends the XML
};

// Parses the XML up to the <AppendedData> start tag, or all of it when there is none (the bytes
// after that tag may be raw binary; VTK ends its XML there too). Throws MeshReadError
// "path:line: what" for XML that is not well-formed, for text that is not ASCII-compatible, and
// for what VTK would read differently from the XML: an element written by an entity reference (VTK
// finds data by byte position), a '>' inside an attribute value of a DataArray or AppendedData
// tag (VTK takes the first '>' for the tag's end), a "<AppendedData" before the AppendedData
// element (VTK ends the XML at the first one, even in a comment), and an <AppendedData> that is
// not a child of the root.
VtpXml readVtpXml(const std::string& path, std::string_view bytes);

// What vtkXMLParser::IsSpace accepts (isspace in the C locale): the blanks VTK skips before data.
bool isVtkSpace(char c);

// The bytes VTK reads as an inline array's data: from the end of its start tag up to the first '<'
// or '&' (no data in any encoding holds either). For a self-closed tag that is the text after it.
std::string_view textVtkReadsAfterTag(std::string_view bytes, const VtpElement& element);

// The element's content between its start and end tags as it stands in the file (empty when
// self-closed or never closed).
std::string_view contentBytes(std::string_view bytes, const VtpElement& element);

// The appended data as vtkXMLDataParser finds it: after the AppendedData start tag, blanks and
// the '_' marker, up to the last "</AppendedData>" (or the end of the file). Nothing when the
// first character after the blanks is not '_'.
std::optional<std::string_view> appendedDataBytes(std::string_view bytes, const VtpElement& appendedData);

}  // namespace conescope
