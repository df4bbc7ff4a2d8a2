// .pvd collections: written by hand (the format is five lines), read with VTK's XML parser.
#include "ui/vis/PvdSeries.h"

#include "solver/io/SafeFile.h"

#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lbdem::vis {

namespace {

/// Escapes the characters XML attributes cannot hold literally.
std::string xmlEscape(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

/// The shortest decimal text that reads back as exactly `value`.
std::string shortestText(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

} // namespace

void writeTextAtomically(const std::string& path, const std::string& text) {
    io::replaceFile(path, text, false);
}

PvdSeries::PvdSeries(std::string path, bool resume) : m_path(std::move(path)) {
    if (resume && std::filesystem::exists(m_path)) m_entries = readPvd(m_path);
}

void PvdSeries::append(double time_s, const std::string& file) {
    m_entries.push_back({time_s, file});
    rewrite();
}

void PvdSeries::dropAfter(double time_s) {
    const auto before = m_entries.size();
    m_entries.erase(
        std::remove_if(m_entries.begin(), m_entries.end(),
                       [time_s](const PvdEntry& entry) { return entry.time_s > time_s; }),
        m_entries.end());
    if (m_entries.size() != before) rewrite();
}

void PvdSeries::rewrite() const {
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const PvdEntry& entry : m_entries)
        xml << "    <DataSet timestep=\"" << shortestText(entry.time_s)
            << "\" group=\"\" part=\"0\" file=\"" << xmlEscape(entry.file) << "\"/>\n";
    xml << "  </Collection>\n</VTKFile>\n";
    writeTextAtomically(m_path, xml.str());
}

std::vector<PvdEntry> readPvd(const std::string& path) {
    if (!std::filesystem::exists(path)) throw std::runtime_error("no such series file " + path);
    vtkSmartPointer<vtkXMLDataElement> root;
    root.TakeReference(vtkXMLUtilities::ReadElementFromFile(path.c_str()));
    const char* type = root ? root->GetAttribute("type") : nullptr;
    if (!root || std::string(root->GetName()) != "VTKFile" || !type ||
        std::string(type) != "Collection")
        throw std::runtime_error(path + " is not a VTK .pvd collection file");
    std::vector<PvdEntry> entries;
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    if (!collection) return entries;
    for (int k = 0; k < collection->GetNumberOfNestedElements(); ++k) {
        vtkXMLDataElement* element = collection->GetNestedElement(k);
        if (std::string(element->GetName()) != "DataSet" || !element->GetAttribute("file"))
            continue;
        double time = 0;
        element->GetScalarAttribute("timestep", time);
        entries.push_back({time, element->GetAttribute("file")});
    }
    return entries;
}

} // namespace lbdem::vis
