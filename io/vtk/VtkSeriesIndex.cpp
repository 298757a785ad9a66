#include "io/vtk/VtkSeriesIndex.h"

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

namespace eikon::io {
namespace {

// Shortest text that reads back as the same double (valid in XML and JSON;
// callers have checked that the value is finite).
std::string formatDouble(double value) {
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    EIKON_CHECK(result.ec == std::errc());
    return std::string(buffer.data(), result.ptr);
}

}  // namespace

bool isSafeVtkBaseName(const std::string& name) {
    if (name.empty() || name == "." || name == "..") return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
               c == '.';
    });
}

VtkSeriesIndex::VtkSeriesIndex(std::filesystem::path directory, std::string baseName, std::string extension)
    : directory_(std::move(directory)), baseName_(std::move(baseName)), extension_(std::move(extension)) {
    EIKON_CHECK(isSafeVtkBaseName(baseName_) && isSafeVtkBaseName(extension_));
}

std::filesystem::path VtkSeriesIndex::framePath(int frame) const {
    char number[16];
    std::snprintf(number, sizeof number, "%05d", frame);
    return directory_ / (baseName_ + "_" + number + "." + extension_);
}

std::filesystem::path VtkSeriesIndex::collectionPath() const { return directory_ / (baseName_ + ".pvd"); }

std::filesystem::path VtkSeriesIndex::seriesPath() const {
    return directory_ / (baseName_ + "." + extension_ + ".series");
}

void VtkSeriesIndex::add(int frame, double time) {
    record(frame, time);
    if (!deferred_) write();
}

void VtkSeriesIndex::record(int frame, double time) {
    EIKON_CHECK_MSG(frame >= 0 && std::isfinite(time), "frame " + std::to_string(frame));
    frameTimes_[frame] = time;
}

void VtkSeriesIndex::write() const {
    std::string pvd =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        "  <Collection>\n";
    std::string series = "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
    bool first = true;
    for (const auto& [number, t] : frameTimes_) {
        const std::string file = framePath(number).filename().string();  // relative: beside the index files
        const std::string text = formatDouble(t);
        pvd += "    <DataSet timestep=\"" + text + "\" group=\"\" part=\"0\" file=\"" + file + "\"/>\n";
        series += std::string(first ? "" : ",\n") + "    { \"name\" : \"" + file + "\", \"time\" : " + text + " }";
        first = false;
    }
    pvd += "  </Collection>\n</VTKFile>\n";
    series += "\n  ]\n}\n";
    writeFileAtomically(collectionPath(), pvd);
    writeFileAtomically(seriesPath(), series);
}

}  // namespace eikon::io
