#include "io/files/RunJournal.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <sstream>
#include <system_error>

#include <unistd.h>

namespace eikon::io {

namespace {

constexpr std::string_view kHeaderStart = "# eikon run journal, format 2, pid ";

constexpr std::array<std::pair<JournalEntry::Kind, std::string_view>, 4> kKindNames = {{
    {JournalEntry::Kind::Intent, "new"},
    {JournalEntry::Kind::File, "file"},
    {JournalEntry::Kind::Folder, "folder"},
    {JournalEntry::Kind::Share, "share"},
}};

constexpr std::string_view kSceneKind = "scene\t";

// One line in one write(2).
void writeLine(int journal, const std::string& line) {
    const ssize_t written = ::write(journal, line.data(), line.size());
    if (written != static_cast<ssize_t>(line.size()))  // a short write: the disk is full
        throw std::system_error(written < 0 ? errno : ENOSPC, std::generic_category(), "cannot record it");
}

template <typename Number>
bool parseNumber(const std::string& text, Number& value) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc{} && end == text.data() + text.size();
}

std::optional<JournalEntry> parseEntry(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream split(line);
    for (std::string field; std::getline(split, field, '\t');) fields.push_back(field);
    if (fields.empty()) return std::nullopt;
    JournalEntry entry;
    bool known = false;
    for (const auto& [kind, name] : kKindNames)
        if (fields[0] == name) entry.kind = kind, known = true;
    if (!known) return std::nullopt;
    const bool intent = entry.kind == JournalEntry::Kind::Intent;
    if (fields.size() != (intent ? 2u : 4u)) return std::nullopt;
    if (!intent && !(parseNumber(fields[1], entry.identity.device) && parseNumber(fields[2], entry.identity.inode)))
        return std::nullopt;
    entry.path = fields.back();
    if (!isPlainRelative(entry.path)) return std::nullopt;
    return entry;
}

}  // namespace

std::string journalHeader(pid_t pid) {
    return std::string(kHeaderStart) + std::to_string(pid) +
           ": the files and folders eikon created in this folder, by device and inode; `--force` removes "
           "each only while it is still the same file\n";
}

std::optional<long> journalPid(const std::string& text) {
    if (text.compare(0, kHeaderStart.size(), kHeaderStart) != 0) return std::nullopt;
    const std::string rest = text.substr(kHeaderStart.size(), text.find(':') - kHeaderStart.size());
    long pid = 0;
    if (!parseNumber(rest, pid)) return std::nullopt;
    return pid;
}

std::vector<JournalEntry> journalEntries(const std::string& text) {
    std::vector<JournalEntry> entries;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (const std::optional<JournalEntry> entry = parseEntry(line)) entries.push_back(*entry);
    return entries;
}

void appendToJournal(int journal, const JournalEntry& entry) {
    const std::string path = entry.path.generic_string();
    if (path.find_first_of("\t\n") != std::string::npos)
        throw std::system_error(EINVAL, std::generic_category(), "a name holding a tab or line break cannot be recorded");
    std::string line;
    for (const auto& [kind, name] : kKindNames)
        if (entry.kind == kind) line = name;
    if (entry.kind != JournalEntry::Kind::Intent)
        line += "\t" + std::to_string(entry.identity.device) + "\t" + std::to_string(entry.identity.inode);
    line += "\t" + path + "\n";
    writeLine(journal, line);
}

void appendSceneToJournal(int journal, const std::string& fingerprint) {
    if (fingerprint.empty() || fingerprint.find_first_of("\t\n") != std::string::npos)
        throw std::system_error(EINVAL, std::generic_category(), "a scene fingerprint must be one word");
    writeLine(journal, std::string(kSceneKind) + fingerprint + "\n");
}

std::optional<std::string> journalScene(const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (line.compare(0, kSceneKind.size(), kSceneKind) == 0 && line.size() > kSceneKind.size())
            return line.substr(kSceneKind.size());
    return std::nullopt;
}

std::string readWholeFile(int fd) {
    std::string text;
    std::array<char, 65536> buffer;
    for (off_t offset = 0;;) {
        const ssize_t got = ::pread(fd, buffer.data(), buffer.size(), offset);
        if (got < 0) throw std::system_error(errno, std::generic_category(), "cannot read");
        if (got == 0) return text;
        text.append(buffer.data(), static_cast<std::size_t>(got));
        offset += got;
    }
}

}  // namespace eikon::io
