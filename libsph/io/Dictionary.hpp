// OpenFOAM-syntax dictionaries: `key value;`, nested `{ }`, lists `( )`, `//` and `/* */`
// comments, `#include "file"`, `$macro` substitution (`$name`, `$outer/inner`), scientific
// numbers. Every token keeps its file, line and column, so each error a user can make names
// where it is. Look-ups mark entries as used; checkUnused() turns a misspelt or stray keyword
// into an error instead of a silently ignored line.
#pragma once

#include "core/FatalError.hpp"
#include "core/Vector.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace sph {

struct Token {
    enum class Kind { Word, Number, String, Punctuation };
    Kind kind = Kind::Word;
    std::string text;
    double number = 0.0;
    SourceLocation where;

    std::string describe() const;  // "number 3.5", "word 'abc'", ...
};

class Dictionary;

class Entry {
public:
    Entry(std::string keyword, SourceLocation where, std::vector<Token> tokens);
    Entry(std::string keyword, SourceLocation where, std::shared_ptr<Dictionary> dictionary);

    const std::string& keyword() const { return keyword_; }
    const SourceLocation& where() const { return where_; }
    bool isDictionary() const { return dictionary_ != nullptr; }
    const std::vector<Token>& tokens() const { return tokens_; }
    const Dictionary& dictionary() const { return *dictionary_; }
    const std::shared_ptr<Dictionary>& sharedDictionary() const { return dictionary_; }

    bool used = false;

private:
    std::string keyword_;
    SourceLocation where_;
    std::vector<Token> tokens_;
    std::shared_ptr<Dictionary> dictionary_;
};

class Dictionary {
public:
    Dictionary(std::string name, SourceLocation where) : name_(std::move(name)), where_(std::move(where)) {}

    // Reads and parses a file; a missing or unreadable file is a FatalError naming it.
    static Dictionary fromFile(const std::filesystem::path& file, const std::string& name = "");
    // Parses text; `sourceName` stands for the file in messages and `#include` is relative to `baseDirectory`.
    static Dictionary fromString(const std::string& text, const std::string& sourceName, const std::filesystem::path& baseDirectory = ".");

    const std::string& name() const { return name_; }
    const SourceLocation& where() const { return where_; }

    bool found(const std::string& keyword) const;
    std::vector<std::string> keywords() const;
    std::size_t tokenCount() const;                            // entries and value tokens, sub-dictionaries included
    const Entry* findEntry(const std::string& keyword) const;  // marks it used; nullptr if absent
    const Entry& entry(const std::string& keyword) const;      // FatalError if absent

    const Dictionary& subDict(const std::string& keyword) const;
    const Dictionary* findSubDict(const std::string& keyword) const;

    // Typed look-up. T: double, int, bool, std::string, std::vector<double>, std::vector<std::string>.
    template <class T>
    T get(const std::string& keyword) const;
    template <class T>
    T getOrDefault(const std::string& keyword, const T& fallback) const {
        return found(keyword) ? get<T>(keyword) : fallback;
    }
    double getPositive(const std::string& keyword) const;
    double getNonNegative(const std::string& keyword) const;
    double getPositiveOrDefault(const std::string& keyword, double fallback) const;
    double getNonNegativeOrDefault(const std::string& keyword, double fallback) const;
    template <int D>
    Vec<D> getVector(const std::string& keyword) const;
    template <int D>
    std::vector<Vec<D>> getVectorList(const std::string& keyword) const;  // ((x y) (x y) ...)

    // A FatalError for a value that read correctly but is not acceptable.
    [[noreturn]] void fail(const std::string& keyword, const std::string& message) const;
    // The same for a value that is accepted but known to give wrong results: printed to stdout
    // (rank 0's alone in a parallel run) and the run goes on.
    void warn(const std::string& keyword, const std::string& message) const;

    // FatalError listing every entry (recursively) that no look-up has used, each with the
    // keyword a look-up asked for and did not find that its spelling is nearest to, if any is
    // near ("did you mean").
    void checkUnused() const;

    // Parser interface.
    void add(Entry entry);
    void merge(const Dictionary& other);

private:
    void collectUnused(std::vector<std::string>& out) const;
    Entry* lookup(const std::string& keyword) const;

    std::string name_;
    SourceLocation where_;
    mutable std::vector<Entry> entries_;
    mutable std::vector<std::string> missed_;  // keywords a look-up asked for and did not find
};

}  // namespace sph
