#include "io/Dictionary.hpp"

#include "core/Spelling.hpp"
#include "io/DictionaryExpression.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sph {

namespace {

constexpr int maxIncludeDepth = 32;
// Limits that turn a runaway input into a message: nesting deeper than any case needs would
// overflow the parser's stack, and macros that double at every level would fill the memory.
constexpr int maxNestingDepth = 100;
constexpr std::size_t maxTokens = 2'000'000;

bool isPunctuation(char c) { return c == '{' || c == '}' || c == '(' || c == ')' || c == ';' || c == '[' || c == ']'; }

// Splits text into tokens; comments are dropped here.
class Tokenizer {
public:
    Tokenizer(const std::string& text, std::shared_ptr<const std::string> file) : text_(text), file_(std::move(file)) {}

    std::vector<Token> run() {
        std::vector<Token> tokens;
        while (skipBlanksAndComments()) {
            tokens.push_back(next());
            if (tokens.size() > maxTokens)
                throw FatalError(tokens.back().where, "more than " + std::to_string(maxTokens) + " tokens in one dictionary");
        }
        return tokens;
    }

private:
    SourceLocation here() const { return {file_, line_, column_}; }

    char peek(std::size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }

    void advance() {
        if (text_[pos_] == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
        ++pos_;
    }

    // Returns false at end of text.
    bool skipBlanksAndComments() {
        while (pos_ < text_.size()) {
            const char c = peek();
            if (std::isspace(static_cast<unsigned char>(c))) {
                advance();
            } else if (c == '/' && peek(1) == '/') {
                while (pos_ < text_.size() && peek() != '\n') advance();
            } else if (c == '/' && peek(1) == '*') {
                const SourceLocation start = here();
                advance();
                advance();
                while (pos_ < text_.size() && !(peek() == '*' && peek(1) == '/')) advance();
                if (pos_ >= text_.size()) throw FatalError(start, "comment '/*' is never closed by '*/'");
                advance();
                advance();
            } else {
                return true;
            }
        }
        return false;
    }

    Token next() {
        Token token;
        token.where = here();
        const char c = peek();
        if (isPunctuation(c)) {
            token.kind = Token::Kind::Punctuation;
            token.text = std::string(1, c);
            advance();
            return token;
        }
        if (c == '"') {
            token.kind = Token::Kind::String;
            advance();
            while (pos_ < text_.size() && peek() != '"' && peek() != '\n') {
                if (peek() == '\\' && (peek(1) == '"' || peek(1) == '\\')) advance();
                token.text += peek();
                advance();
            }
            if (peek() != '"') throw FatalError(token.where, "string is not closed by '\"' on the same line");
            advance();
            return token;
        }
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(peek())) && !isPunctuation(peek()) && peek() != '"' &&
               !(peek() == '/' && (peek(1) == '/' || peek(1) == '*'))) {
            token.text += peek();
            advance();
        }
        token.kind = Token::Kind::Word;
        const bool hasDigit = std::any_of(token.text.begin(), token.text.end(), [](char d) { return std::isdigit(static_cast<unsigned char>(d)); });
        const char first = token.text.front();
        if (hasDigit && (std::isdigit(static_cast<unsigned char>(first)) || first == '-' || first == '+' || first == '.')) {
            char* end = nullptr;
            errno = 0;
            const double value = std::strtod(token.text.c_str(), &end);
            if (end == token.text.c_str() + token.text.size()) {
                // strtod reports overflow (and underflow) through errno and returns inf or 0.
                if (errno == ERANGE && (std::isinf(value) || value == 0.0))
                    throw FatalError(token.where,
                                     "number " + token.text + " is outside the range of a double (magnitudes 2.2e-308 to 1.8e308, or 0)");
                token.kind = Token::Kind::Number;
                token.number = value;
            }
        }
        return token;
    }

    const std::string& text_;
    std::shared_ptr<const std::string> file_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

std::string readFile(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw FatalError("error: cannot open dictionary '" + file.string() + "': file not found");
    if (std::filesystem::is_directory(file, ec)) throw FatalError("error: cannot open dictionary '" + file.string() + "': it is a directory");
    // A device or pipe (an #include "/dev/zero") would never end.
    if (!std::filesystem::is_regular_file(file, ec)) throw FatalError("error: cannot open dictionary '" + file.string() + "': not a regular file");
    constexpr std::uintmax_t maxBytes = 16u << 20;
    if (const std::uintmax_t bytes = std::filesystem::file_size(file, ec); !ec && bytes > maxBytes)
        throw FatalError("error: cannot read dictionary '" + file.string() + "': it is " + std::to_string(bytes >> 20) +
                         " MiB, more than the 16 MiB a dictionary may have (put tables in a .csv file)");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw FatalError("error: cannot open dictionary '" + file.string() + "': permission denied or unreadable");
    std::ostringstream contents;
    contents << in.rdbuf();
    return contents.str();
}

// Recursive-descent parser over the token list of one file.
class Parser {
public:
    // `tokenCount` counts every token and entry the file and its includes build, macros expanded.
    Parser(std::vector<Token> tokens, std::filesystem::path baseDirectory, int includeDepth, int nesting, std::vector<const Dictionary*> scopes,
           std::size_t& tokenCount)
        : tokens_(std::move(tokens)),
          base_(std::move(baseDirectory)),
          depth_(includeDepth),
          nesting_(nesting),
          scopes_(std::move(scopes)),
          tokenCount_(tokenCount) {
        count(tokens_.size(), tokens_.empty() ? SourceLocation{} : tokens_.front().where);
    }

    // Parses entries into `target` until end of input (topLevel) or a closing '}'.
    void parseBody(Dictionary& target, bool topLevel) {
        const std::size_t enclosingScopes = scopes_.size();  // parameter files opened here end with this body
        scopes_.push_back(&target);
        while (pos_ < tokens_.size()) {
            const Token& token = tokens_[pos_];
            if (token.kind == Token::Kind::Punctuation) {
                if (token.text == "}") {
                    if (topLevel) throw FatalError(token.where, "'}' has no matching '{'");
                    ++pos_;
                    scopes_.resize(enclosingScopes);
                    return;
                }
                if (token.text == ";") {  // stray ';' is harmless, as in OpenFOAM
                    ++pos_;
                    continue;
                }
                throw FatalError(token.where, "expected a keyword, found " + token.describe());
            }
            if (token.kind == Token::Kind::Number) throw FatalError(token.where, "expected a keyword, found " + token.describe());
            if (token.kind == Token::Kind::Word && token.text == "#include") {
                parseInclude(target);
                continue;
            }
            if (token.kind == Token::Kind::Word && token.text == "#includeParameters") {
                parseParameters();
                continue;
            }
            if (token.kind == Token::Kind::Word && token.text == "#eval")
                throw FatalError(token.where, "#eval gives a value and stands after a keyword, as in: length #eval \"2 * $H\";");
            if (token.kind == Token::Kind::Word && token.text.starts_with("#"))
                throw FatalError(token.where, "unknown directive '" + token.text + "' (valid: #include, #includeParameters, and #eval in a value)");
            if (token.kind == Token::Kind::Word && token.text.starts_with("$")) {
                // `$dict` inside a dictionary merges that dictionary's entries here. A copy of the
                // entry keeps its dictionary alive while the merge replaces entries of the same
                // name (`$type` in a dictionary with a sub-dictionary `type`: found by fuzzing).
                const Entry source = resolveMacro(token);
                if (!source.isDictionary())
                    throw FatalError(token.where, "'" + token.text + "' names a value, not a dictionary, so it cannot stand as an entry");
                count(source.dictionary().tokenCount(), token.where);
                target.merge(source.dictionary());
                ++pos_;
                if (pos_ < tokens_.size() && tokens_[pos_].text == ";" && tokens_[pos_].kind == Token::Kind::Punctuation) ++pos_;
                continue;
            }
            parseEntry(target);
        }
        if (!topLevel) {
            throw FatalError(target.where(), "dictionary '" + target.name() + "' opened by '{' is never closed by '}'");
        }
        scopes_.resize(enclosingScopes);
    }

private:
    void parseInclude(Dictionary& target) {
        auto [inner, file] = openIncluded();
        inner.scopes_.pop_back();  // the included text parses straight into `target`
        inner.parseBody(target, true);
    }

    // #includeParameters "file": the file's entries serve the macros and #eval of the rest of
    // this dictionary (and those nested in it) but are not its entries, so a dictionary that
    // does not use them all is no error: one parameter file for every dictionary of a case.
    void parseParameters() {
        auto [inner, file] = openIncluded();
        auto parameters =
            std::make_shared<Dictionary>(file.filename().string(), SourceLocation{std::make_shared<const std::string>(file.string()), 0, 0});
        inner.parseBody(*parameters, true);
        parameterFiles_.push_back(parameters);
        scopes_.insert(scopes_.end() - 1, parameters.get());  // below the dictionary's own entries, which come first
    }

    // The parser of the file an #include or #includeParameters names, and its path.
    std::pair<Parser, std::filesystem::path> openIncluded() {
        const Token& directive = tokens_[pos_++];
        if (pos_ >= tokens_.size() || tokens_[pos_].kind != Token::Kind::String)
            throw FatalError(directive.where, directive.text + " must be followed by a file name in double quotes");
        const Token& fileToken = tokens_[pos_++];
        if (depth_ >= maxIncludeDepth)
            throw FatalError(fileToken.where, directive.text + " nested more than " + std::to_string(maxIncludeDepth) + " deep (an include cycle?)");
        std::filesystem::path file = fileToken.text;
        if (file.is_relative()) file = base_ / file;
        std::string text;
        try {
            text = readFile(file);
        } catch (const FatalError& e) {
            throw FatalError(fileToken.where, directive.text + " \"" + fileToken.text + "\": " + e.what());
        }
        auto fileName = std::make_shared<const std::string>(file.lexically_normal().string());
        return {Parser(Tokenizer(text, fileName).run(), file.parent_path(), depth_ + 1, nesting_, scopes_, tokenCount_), file.lexically_normal()};
    }

    // #eval "expression": the macros in it replaced by their numbers, then evaluated.
    Token evaluate() {
        const Token& directive = tokens_[pos_++];
        if (pos_ >= tokens_.size() || tokens_[pos_].kind != Token::Kind::String)
            throw FatalError(directive.where, "#eval must be followed by an expression in double quotes, as in: length #eval \"2 * $H\";");
        const Token& expression = tokens_[pos_++];
        Token result;
        result.kind = Token::Kind::Number;
        result.where = expression.where;
        result.number = evaluateDictionaryExpression(expandNumberMacros(expression), expression.where);
        char digits[32];
        const auto written = std::to_chars(digits, digits + sizeof digits, result.number);  // shortest text that reads back exactly
        result.text.assign(digits, written.ptr);
        return result;
    }

    // The expression's text with each $name or ${path/name} replaced by the number it names,
    // in parentheses (so that a negative one keeps its sign under ^).
    std::string expandNumberMacros(const Token& expression) const {
        const std::string& text = expression.text;
        std::string expanded;
        for (std::size_t i = 0; i < text.size();) {
            if (text[i] != '$') {
                expanded += text[i++];
                continue;
            }
            const std::size_t start = i++;
            if (i < text.size() && text[i] == '{') {
                const std::size_t close = text.find('}', i);
                if (close == std::string::npos) throw FatalError(expression.where, "#eval \"" + text + "\": '${' is never closed by '}'");
                i = close + 1;
            } else {
                while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) ++i;
            }
            Token macro = expression;
            macro.text = text.substr(start, i - start);
            const Entry& source = resolveMacro(macro);
            if (source.isDictionary() || source.tokens().size() != 1 || source.tokens().front().kind != Token::Kind::Number)
                throw FatalError(expression.where, "#eval \"" + text + "\": macro '" + macro.text + "' must name one number; it names " +
                                                       (source.isDictionary()         ? std::string("a dictionary")
                                                        : source.tokens().size() != 1 ? std::to_string(source.tokens().size()) + " tokens"
                                                                                      : source.tokens().front().describe()));
            expanded += "(" + source.tokens().front().text + ")";
        }
        return expanded;
    }

    const Entry& resolveMacro(const Token& token) const {
        std::string path = token.text.substr(1);
        if (path.starts_with("{") && path.ends_with("}")) path = path.substr(1, path.size() - 2);
        if (path.empty()) throw FatalError(token.where, "'$' must be followed by the name of an entry");
        std::vector<std::string> parts;
        std::stringstream stream(path);
        for (std::string part; std::getline(stream, part, '/');) parts.push_back(part);
        for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope) {
            const Dictionary* dict = *scope;
            const Entry* found = nullptr;
            for (std::size_t i = 0; i < parts.size(); ++i) {
                found = dict->findEntry(parts[i]);
                if (!found) break;
                if (i + 1 < parts.size()) {
                    if (!found->isDictionary()) {
                        found = nullptr;
                        break;
                    }
                    dict = &found->dictionary();
                }
            }
            if (found) return *found;
        }
        throw FatalError(token.where, "macro '" + token.text + "' refers to no entry defined before it in this or an enclosing dictionary");
    }

    // A keyword followed by '{': a sub-dictionary.
    void parseSubDictionary(Dictionary& target, const Token& keyword, const std::string& childName) {
        if (nesting_ >= maxNestingDepth)
            throw FatalError(tokens_[pos_].where, "dictionaries nested more than " + std::to_string(maxNestingDepth) + " deep");
        auto child = std::make_shared<Dictionary>(childName, tokens_[pos_].where);
        ++pos_;
        ++nesting_;
        parseBody(*child, false);
        --nesting_;
        target.add(Entry(keyword.text, keyword.where, child));
    }

    // A punctuation token in the value of `keyword`, checked against the lists still open:
    // true at the ';' that ends the value.
    static bool endsValue(const Token& token, const Token& keyword, std::vector<const Token*>& open) {
        if (token.text == ";" && open.empty()) return true;
        if (token.text == "(" || token.text == "[") open.push_back(&token);
        if (token.text == ")" || token.text == "]") {
            const char expected = token.text == ")" ? '(' : '[';
            if (open.empty() || open.back()->text[0] != expected)
                throw FatalError(token.where, "'" + token.text + "' has no matching '" + std::string(1, expected) + "'");
            open.pop_back();
        }
        if (token.text == "{" || token.text == "}" || (token.text == ";" && !open.empty())) {
            if (!open.empty())
                throw FatalError(token.where, "found '" + token.text + "' inside the list opened at line " + std::to_string(open.back()->where.line) +
                                                  "; is a ')' missing?");
            throw FatalError(token.where, "found '" + token.text + "' in the value of '" + keyword.text + "'; is a ';' missing after it?");
        }
        return false;
    }

    void parseEntry(Dictionary& target) {
        const Token& keyword = tokens_[pos_++];
        const std::string childName = target.name().empty() ? keyword.text : target.name() + "/" + keyword.text;
        if (pos_ < tokens_.size() && tokens_[pos_].kind == Token::Kind::Punctuation && tokens_[pos_].text == "{") {
            parseSubDictionary(target, keyword, childName);
            return;
        }
        std::vector<Token> value;
        std::vector<const Token*> open;  // unclosed '(' and '['
        while (true) {
            if (pos_ >= tokens_.size()) {
                if (!open.empty()) throw FatalError(open.back()->where, "'" + open.back()->text + "' is never closed");
                throw FatalError(keyword.where, "entry '" + keyword.text + "' is not terminated by ';' before the end of the file");
            }
            const Token& token = tokens_[pos_];
            if (token.kind == Token::Kind::Punctuation && endsValue(token, keyword, open)) {
                ++pos_;
                break;
            }
            if (token.kind == Token::Kind::Word && token.text.starts_with("$")) {
                const Entry source = resolveMacro(token);  // a copy, as above
                ++pos_;
                if (source.isDictionary()) {
                    if (!value.empty() || pos_ >= tokens_.size() || tokens_[pos_].text != ";")
                        throw FatalError(token.where, "'" + token.text + "' names a dictionary and can only stand alone as a value");
                    ++pos_;
                    count(source.dictionary().tokenCount(), token.where);
                    auto copy = std::make_shared<Dictionary>(childName, token.where);
                    copy->merge(source.dictionary());
                    target.add(Entry(keyword.text, keyword.where, copy));
                    return;
                }
                count(source.tokens().size(), token.where);
                value.insert(value.end(), source.tokens().begin(), source.tokens().end());
                continue;
            }
            if (token.kind == Token::Kind::Word && token.text == "#eval") {
                value.push_back(evaluate());
                continue;
            }
            value.push_back(token);
            ++pos_;
        }
        if (value.empty()) throw FatalError(keyword.where, "entry '" + keyword.text + "' has no value before ';'");
        target.add(Entry(keyword.text, keyword.where, std::move(value)));
    }

    void count(std::size_t added, const SourceLocation& where) {
        tokenCount_ += added;
        if (tokenCount_ > maxTokens)
            throw FatalError(
                where, "the dictionary expands to more than " + std::to_string(maxTokens) + " tokens (macros that copy each other at every level?)");
    }

    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
    std::filesystem::path base_;
    int depth_;
    int nesting_;
    std::vector<const Dictionary*> scopes_;
    std::vector<std::shared_ptr<const Dictionary>> parameterFiles_;  // alive while their scopes are
    std::size_t& tokenCount_;
};

std::string joinTokens(const std::vector<Token>& tokens) {
    std::string text;
    for (const Token& t : tokens) {
        if (!text.empty()) text += ' ';
        text += t.kind == Token::Kind::String ? "\"" + t.text + "\"" : t.text;
    }
    return text;
}

}  // namespace

std::string Token::describe() const {
    switch (kind) {
        case Kind::Number: return "number " + text;
        case Kind::String: return "string \"" + text + "\"";
        case Kind::Punctuation: return "'" + text + "'";
        case Kind::Word: break;
    }
    return "word '" + text + "'";
}

Entry::Entry(std::string keyword, SourceLocation where, std::vector<Token> tokens)
    : keyword_(std::move(keyword)), where_(std::move(where)), tokens_(std::move(tokens)) {}

Entry::Entry(std::string keyword, SourceLocation where, std::shared_ptr<Dictionary> dictionary)
    : keyword_(std::move(keyword)), where_(std::move(where)), dictionary_(std::move(dictionary)) {}

Dictionary Dictionary::fromFile(const std::filesystem::path& file, const std::string& name) {
    const std::string text = readFile(file);
    auto fileName = std::make_shared<const std::string>(file.lexically_normal().string());
    Dictionary dict(name.empty() ? file.filename().string() : name, SourceLocation{fileName, 0, 0});
    std::size_t tokenCount = 0;
    Parser(Tokenizer(text, fileName).run(), file.parent_path(), 0, 0, {}, tokenCount).parseBody(dict, true);
    return dict;
}

Dictionary Dictionary::fromString(const std::string& text, const std::string& sourceName, const std::filesystem::path& baseDirectory) {
    auto fileName = std::make_shared<const std::string>(sourceName);
    Dictionary dict(sourceName, SourceLocation{fileName, 0, 0});
    std::size_t tokenCount = 0;
    Parser(Tokenizer(text, fileName).run(), baseDirectory, 0, 0, {}, tokenCount).parseBody(dict, true);
    return dict;
}

void Dictionary::add(Entry entry) {
    // A repeated keyword replaces the earlier one, as in OpenFOAM.
    for (Entry& existing : entries_) {
        if (existing.keyword() == entry.keyword()) {
            existing = std::move(entry);
            return;
        }
    }
    entries_.push_back(std::move(entry));
}

void Dictionary::merge(const Dictionary& other) {
    for (const Entry& e : other.entries_) {
        if (e.isDictionary()) {
            auto copy = std::make_shared<Dictionary>(name_ + "/" + e.keyword(), e.dictionary().where());
            copy->merge(e.dictionary());
            add(Entry(e.keyword(), e.where(), copy));
        } else {
            add(Entry(e.keyword(), e.where(), e.tokens()));
        }
    }
}

Entry* Dictionary::lookup(const std::string& keyword) const {
    for (Entry& e : entries_)
        if (e.keyword() == keyword) return &e;
    if (std::find(missed_.begin(), missed_.end(), keyword) == missed_.end()) missed_.push_back(keyword);
    return nullptr;
}

std::size_t Dictionary::tokenCount() const {
    std::size_t size = 0;
    for (const Entry& e : entries_) size += 1 + (e.isDictionary() ? e.dictionary().tokenCount() : e.tokens().size());
    return size;
}

bool Dictionary::found(const std::string& keyword) const { return lookup(keyword) != nullptr; }

std::vector<std::string> Dictionary::keywords() const {
    std::vector<std::string> names;
    for (const Entry& e : entries_) names.push_back(e.keyword());
    return names;
}

const Entry* Dictionary::findEntry(const std::string& keyword) const {
    Entry* e = lookup(keyword);
    if (e) e->used = true;
    return e;
}

const Entry& Dictionary::entry(const std::string& keyword) const {
    const Entry* e = findEntry(keyword);
    if (!e) {
        std::string message = "keyword '" + keyword + "' is missing from dictionary '" + name_ + "'";
        std::vector<std::string> unused;
        for (const Entry& other : entries_)
            if (!other.used) unused.push_back(other.keyword());
        const std::string nearest = nearestSpelling(keyword, unused);
        if (!nearest.empty()) message += " (is '" + nearest + "' at " + lookup(nearest)->where().str() + " misspelt?)";
        throw FatalError(where_, message);
    }
    return *e;
}

const Dictionary* Dictionary::findSubDict(const std::string& keyword) const {
    const Entry* e = findEntry(keyword);
    if (!e) return nullptr;
    if (!e->isDictionary())
        throw FatalError(e->where(), "'" + keyword + "' in dictionary '" + name_ + "' must be a dictionary { ... }, found the value '" +
                                         joinTokens(e->tokens()) + "'");
    return &e->dictionary();
}

const Dictionary& Dictionary::subDict(const std::string& keyword) const {
    const Entry& e = entry(keyword);
    if (!e.isDictionary())
        throw FatalError(e.where(), "'" + keyword + "' in dictionary '" + name_ + "' must be a dictionary { ... }, found the value '" +
                                        joinTokens(e.tokens()) + "'");
    return e.dictionary();
}

namespace {

const Token& singleToken(const Entry& e, const std::string& dictName, const std::string& expected) {
    if (e.isDictionary())
        throw FatalError(e.where(), "keyword '" + e.keyword() + "' in dictionary '" + dictName + "': expected " + expected + ", found a dictionary");
    if (e.tokens().size() != 1)
        throw FatalError(e.tokens()[1].where, "keyword '" + e.keyword() + "' in dictionary '" + dictName + "': expected " + expected + ", found '" +
                                                  joinTokens(e.tokens()) + "'");
    return e.tokens().front();
}

// Flattens `(a b c)` into its items, checking the brackets.
std::vector<Token> listItems(const Entry& e, const std::string& dictName, const std::string& expected) {
    if (e.isDictionary())
        throw FatalError(e.where(), "keyword '" + e.keyword() + "' in dictionary '" + dictName + "': expected " + expected + ", found a dictionary");
    const auto& t = e.tokens();
    // OpenFOAM allows a size prefix: `3(1 2 3)`.
    std::size_t first = (t.size() >= 2 && t[0].kind == Token::Kind::Number && t[1].text == "(") ? 1 : 0;
    if (t.size() < first + 2 || t[first].text != "(" || t.back().text != ")" || t[first].kind != Token::Kind::Punctuation)
        throw FatalError(t.front().where, "keyword '" + e.keyword() + "' in dictionary '" + dictName + "': expected " + expected +
                                              " in parentheses, found '" + joinTokens(t) + "'");
    std::vector<Token> items(t.begin() + static_cast<long>(first) + 1, t.end() - 1);
    for (const Token& item : items)
        if (item.kind == Token::Kind::Punctuation)
            throw FatalError(item.where, "keyword '" + e.keyword() + "' in dictionary '" + dictName + "': expected " + expected + ", found nested '" +
                                             item.text + "'");
    // Compared as numbers: a prefix such as 1e308 or -1 has no size_t value.
    if (first == 1 && t[0].number != static_cast<double>(items.size()))
        throw FatalError(t[0].where,
                         "keyword '" + e.keyword() + "': list size " + t[0].text + " does not match its " + std::to_string(items.size()) + " items");
    return items;
}

double numberOf(const Token& t, const std::string& keyword, const std::string& dictName) {
    if (t.kind != Token::Kind::Number)
        throw FatalError(t.where, "keyword '" + keyword + "' in dictionary '" + dictName + "': expected a number, found " + t.describe());
    return t.number;
}

}  // namespace

template <>
double Dictionary::get<double>(const std::string& keyword) const {
    const Entry& e = entry(keyword);
    return numberOf(singleToken(e, name_, "a number"), keyword, name_);
}

template <>
int Dictionary::get<int>(const std::string& keyword) const {
    const Entry& e = entry(keyword);
    const Token& t = singleToken(e, name_, "an integer");
    const double value = numberOf(t, keyword, name_);
    // Range first: converting a double outside the integer range is undefined behaviour.
    if (!(value >= -2147483648.0 && value <= 2147483647.0) || value != std::trunc(value))
        throw FatalError(t.where, "keyword '" + keyword + "' in dictionary '" + name_ + "': expected an integer, found " + t.describe());
    return static_cast<int>(value);
}

template <>
bool Dictionary::get<bool>(const std::string& keyword) const {
    const Entry& e = entry(keyword);
    const Token& t = singleToken(e, name_, "a switch (yes/no, true/false, on/off)");
    if (t.text == "yes" || t.text == "true" || t.text == "on") return true;
    if (t.text == "no" || t.text == "false" || t.text == "off") return false;
    throw FatalError(
        t.where, "keyword '" + keyword + "' in dictionary '" + name_ + "': expected a switch (yes/no, true/false, on/off), found " + t.describe());
}

template <>
std::string Dictionary::get<std::string>(const std::string& keyword) const {
    const Entry& e = entry(keyword);
    const Token& t = singleToken(e, name_, "a word");
    if (t.kind != Token::Kind::Word && t.kind != Token::Kind::String)
        throw FatalError(t.where, "keyword '" + keyword + "' in dictionary '" + name_ + "': expected a word, found " + t.describe());
    return t.text;
}

template <>
std::vector<double> Dictionary::get<std::vector<double>>(const std::string& keyword) const {
    std::vector<double> values;
    for (const Token& t : listItems(entry(keyword), name_, "a list of numbers")) values.push_back(numberOf(t, keyword, name_));
    return values;
}

template <>
std::vector<std::string> Dictionary::get<std::vector<std::string>>(const std::string& keyword) const {
    std::vector<std::string> values;
    for (const Token& t : listItems(entry(keyword), name_, "a list of words")) {
        if (t.kind == Token::Kind::Number)
            throw FatalError(t.where, "keyword '" + keyword + "' in dictionary '" + name_ + "': expected a list of words, found " + t.describe());
        values.push_back(t.text);
    }
    return values;
}

template <int D>
Vec<D> Dictionary::getVector(const std::string& keyword) const {
    const std::vector<double> values = get<std::vector<double>>(keyword);
    if (values.size() != static_cast<std::size_t>(D))
        fail(keyword, "expected a vector of " + std::to_string(D) + " components for a " + std::to_string(D) + "D case, found " +
                          std::to_string(values.size()));
    Vec<D> v;
    for (int i = 0; i < D; ++i) v[i] = values[static_cast<std::size_t>(i)];
    return v;
}
template Vec<1> Dictionary::getVector<1>(const std::string&) const;
template Vec<2> Dictionary::getVector<2>(const std::string&) const;
template Vec<3> Dictionary::getVector<3>(const std::string&) const;

template <int D>
std::vector<Vec<D>> Dictionary::getVectorList(const std::string& keyword) const {
    const Entry& e = entry(keyword);
    const auto& t = e.tokens();
    const auto bad = [&]() {
        fail(keyword, std::string("expected a list of ") + std::to_string(D) + "D points " +
                          (D == 1   ? "((x) ...)"
                           : D == 2 ? "((x y) ...)"
                                    : "((x y z) ...)"));
    };
    if (e.isDictionary() || t.size() < 2 || t.front().text != "(" || t.back().text != ")") bad();
    std::vector<Vec<D>> points;
    std::size_t k = 1;
    while (k + 1 < t.size()) {
        if (t[k].text != "(" || k + D + 1 >= t.size() || t[k + D + 1].text != ")") bad();
        Vec<D> x;
        for (int d = 0; d < D; ++d) {
            if (t[k + 1 + d].kind != Token::Kind::Number) bad();
            x[d] = t[k + 1 + d].number;
        }
        points.push_back(x);
        k += D + 2;
    }
    return points;
}
template std::vector<Vec<1>> Dictionary::getVectorList<1>(const std::string&) const;
template std::vector<Vec<2>> Dictionary::getVectorList<2>(const std::string&) const;
template std::vector<Vec<3>> Dictionary::getVectorList<3>(const std::string&) const;

void Dictionary::fail(const std::string& keyword, const std::string& message) const {
    const Entry* e = lookup(keyword);
    throw FatalError(e ? e->where() : where_, "keyword '" + keyword + "' in dictionary '" + name_ + "': " + message);
}

void Dictionary::warn(const std::string& keyword, const std::string& message) const {
    const Entry* e = lookup(keyword);
    fmt::print("{}: warning: keyword '{}' in dictionary '{}': {}\n", (e ? e->where() : where_).str(), keyword, name_, message);
}

double Dictionary::getPositive(const std::string& keyword) const {
    const double value = get<double>(keyword);
    if (!(value > 0.0)) fail(keyword, "must be greater than zero, found " + entry(keyword).tokens().front().text);
    return value;
}

double Dictionary::getNonNegative(const std::string& keyword) const {
    const double value = get<double>(keyword);
    if (!(value >= 0.0)) fail(keyword, "must not be negative, found " + entry(keyword).tokens().front().text);
    return value;
}

double Dictionary::getPositiveOrDefault(const std::string& keyword, double fallback) const {
    return found(keyword) ? getPositive(keyword) : fallback;
}

double Dictionary::getNonNegativeOrDefault(const std::string& keyword, double fallback) const {
    return found(keyword) ? getNonNegative(keyword) : fallback;
}

void Dictionary::collectUnused(std::vector<std::string>& out) const {
    for (const Entry& e : entries_) {
        if (e.keyword() == "FoamFile") continue;  // file header, informational only
        if (!e.used) {
            const std::string nearest = nearestSpelling(e.keyword(), missed_);
            out.push_back(e.where().str() + ": '" + e.keyword() + "' in dictionary '" + name_ + "'" +
                          (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)"));
        } else if (e.isDictionary()) {
            e.dictionary().collectUnused(out);
        }
    }
}

void Dictionary::checkUnused() const {
    std::vector<std::string> unused;
    collectUnused(unused);
    if (unused.empty()) return;
    std::string message = "error: keyword(s) not recognised by the selected models (misspelt, or not used by this selection):";
    for (const std::string& u : unused) message += "\n    " + u;
    throw FatalError(message);
}

}  // namespace sph
