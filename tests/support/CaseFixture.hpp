// Test cases written to a fresh directory under the build tree, one file at a time.
#pragma once

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>

namespace sph::test {

inline std::filesystem::path sourceDirectory() { return SPHKIT_SOURCE_DIR; }

// A new, empty directory named after the running test (and `variant`, for a test that needs several).
inline std::filesystem::path freshDirectory(const std::string& variant = "") {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path dir = std::filesystem::path(SPHKIT_TEST_WORK_DIR) / info->test_suite_name() / info->name();
    if (!variant.empty()) dir /= variant;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline void writeFile(const std::filesystem::path& file, const std::string& text) {
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

// A case's reference data: a .csv file that opens with its '#' source header (a script's output,
// such as damBreak2D's frontComparison.csv after ./Allrun, does not).
inline bool isReferenceData(const std::filesystem::path& file) {
    std::ifstream in(file);
    return file.extension() == ".csv" && in.peek() == '#';
}

// Copies a shipped case's dictionaries (system/, constant/) and reference data into a fresh directory.
inline std::filesystem::path copyCase(const std::string& name, const std::string& variant = "") {
    const std::filesystem::path dir = freshDirectory(variant);
    const std::filesystem::path source = sourceDirectory() / "cases" / name;
    for (const char* part : {"system", "constant"}) std::filesystem::copy(source / part, dir / part, std::filesystem::copy_options::recursive);
    for (const auto& file : std::filesystem::directory_iterator(source))
        if (file.is_regular_file() && isReferenceData(file.path())) std::filesystem::copy(file.path(), dir);
    return dir;
}

// Replaces the first occurrence of `from` in a file (to vary a shipped case).
inline void replaceInFile(const std::filesystem::path& file, const std::string& from, const std::string& to) {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << "'" << from << "' not found in " << file;
    text.replace(at, from.size(), to);
    std::ofstream(file) << text;
}

// Sets `keyword value;` on the line where the keyword starts an entry.
inline void setEntry(const std::filesystem::path& file, const std::string& keyword, const std::string& value) {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::regex entry("(^|\\n)([ \\t]*)" + keyword + "[ \\t]+[^;\\n]*;");
    ASSERT_TRUE(std::regex_search(text, entry)) << "no entry '" << keyword << "' in " << file;
    text = std::regex_replace(text, entry, "$1$2" + keyword + " " + value + ";", std::regex_constants::format_first_only);
    std::ofstream(file) << text;
}

}  // namespace sph::test
