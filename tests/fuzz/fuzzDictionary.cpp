// libFuzzer target: the dictionary parser and every typed look-up on whatever it parsed.
// Bad input must end in a FatalError; any other exception, a crash, a hang or a sanitizer
// report is a finding. Built with -DSPHKIT_FUZZ=ON and clang (see doc/reliability.md).
#include "io/Dictionary.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace {

// Every look-up a model could make of every entry, recursively.
void lookUpEverything(const sph::Dictionary& dict, int depth) {
    for (const std::string& keyword : dict.keywords()) {
        const auto attempt = [&](auto&& lookUp) {
            try {
                lookUp();
            } catch (const sph::FatalError&) {
            }
        };
        attempt([&] { (void)dict.get<double>(keyword); });
        attempt([&] { (void)dict.get<int>(keyword); });
        attempt([&] { (void)dict.get<bool>(keyword); });
        attempt([&] { (void)dict.get<std::string>(keyword); });
        attempt([&] { (void)dict.get<std::vector<double>>(keyword); });
        attempt([&] { (void)dict.get<std::vector<std::string>>(keyword); });
        attempt([&] { (void)dict.getPositive(keyword); });
        attempt([&] { (void)dict.getVector<2>(keyword); });
        attempt([&] { (void)dict.getVector<3>(keyword); });
        attempt([&] {
            if (depth < 8) lookUpEverything(dict.subDict(keyword), depth + 1);
        });
    }
    try {
        dict.checkUnused();
    } catch (const sph::FatalError&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        // #include resolves against a directory with no files: the fuzzer explores the parser,
        // not the file system.
        const sph::Dictionary dict = sph::Dictionary::fromString(text, "fuzz", "/nonexistent");
        lookUpEverything(dict, 0);
    } catch (const sph::FatalError&) {
    }
    return 0;
}
