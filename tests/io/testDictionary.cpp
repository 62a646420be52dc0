#include "io/Dictionary.hpp"
#include "support/CaseFixture.hpp"

#include <gtest/gtest.h>

using sph::Dictionary;
using sph::FatalError;

namespace {

// The message of the FatalError that `f` throws ("" if none).
template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const FatalError& e) {
        return e.what();
    }
    return "";
}

Dictionary parse(const std::string& text) { return Dictionary::fromString(text, "testDict"); }

}  // namespace

TEST(Dictionary, ReadsScalarsWordsSwitchesAndScientificNumbers) {
    const Dictionary d = parse("a 1.5; b -2e-3; c 3E+2; n 42; w tait; s \"a string\"; on yes; off false;");
    EXPECT_DOUBLE_EQ(d.get<double>("a"), 1.5);
    EXPECT_DOUBLE_EQ(d.get<double>("b"), -2e-3);
    EXPECT_DOUBLE_EQ(d.get<double>("c"), 300.0);
    EXPECT_EQ(d.get<int>("n"), 42);
    EXPECT_EQ(d.get<std::string>("w"), "tait");
    EXPECT_EQ(d.get<std::string>("s"), "a string");
    EXPECT_TRUE(d.get<bool>("on"));
    EXPECT_FALSE(d.get<bool>("off"));
}

TEST(Dictionary, ReadsNestedDictionariesListsAndVectors) {
    const Dictionary d = parse("outer { inner { x 1; } list (1 2 3); } words (a b); sized 2(4 5); v (0 -9.81);");
    EXPECT_DOUBLE_EQ(d.subDict("outer").subDict("inner").get<double>("x"), 1.0);
    EXPECT_EQ(d.subDict("outer").get<std::vector<double>>("list"), (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(d.get<std::vector<std::string>>("words"), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(d.get<std::vector<double>>("sized"), (std::vector<double>{4, 5}));
    EXPECT_DOUBLE_EQ((d.getVector<2>("v")[1]), -9.81);
    EXPECT_EQ(d.subDict("outer").subDict("inner").name(), "testDict/outer/inner");
}

TEST(Dictionary, SkipsLineAndBlockComments) {
    const Dictionary d = parse("// line\na 1; /* block\n spanning { lines } */ b 2; // trailing\nc/*inline*/3;");
    EXPECT_DOUBLE_EQ(d.get<double>("a"), 1.0);
    EXPECT_DOUBLE_EQ(d.get<double>("b"), 2.0);
    EXPECT_DOUBLE_EQ(d.get<double>("c"), 3.0);
}

TEST(Dictionary, SubstitutesMacrosFromThisAndEnclosingScopes) {
    const Dictionary d = parse(
        "H 0.6; g (0 -9.81); defaults { gamma 7; }\n"
        "inner { depth $H; gravity $g; eos { $defaults type tait; } copy $defaults; }\n"
        "path $defaults/gamma;");
    const Dictionary& inner = d.subDict("inner");
    EXPECT_DOUBLE_EQ(inner.get<double>("depth"), 0.6);
    EXPECT_EQ(inner.get<std::vector<double>>("gravity"), (std::vector<double>{0, -9.81}));
    EXPECT_DOUBLE_EQ(inner.subDict("eos").get<double>("gamma"), 7.0);
    EXPECT_DOUBLE_EQ(inner.subDict("copy").get<double>("gamma"), 7.0);
    EXPECT_DOUBLE_EQ(d.get<double>("path"), 7.0);
}

TEST(Dictionary, IncludesFilesRelativeToTheIncludingFile) {
    const auto dir = sph::test::freshDirectory();
    sph::test::writeFile(dir / "common" / "values", "rho0 1000; c0 $base;");
    sph::test::writeFile(dir / "main", "base 20;\n#include \"common/values\"\nc0 25; // later entries override\n");
    const Dictionary d = Dictionary::fromFile(dir / "main");
    EXPECT_DOUBLE_EQ(d.get<double>("rho0"), 1000.0);
    EXPECT_DOUBLE_EQ(d.get<double>("c0"), 25.0);
}

TEST(Dictionary, ErrorsNameFileLineAndColumn) {
    EXPECT_EQ(errorOf([] { parse("a 1;\nb 2"); }), "testDict:2:1: error: entry 'b' is not terminated by ';' before the end of the file");
    EXPECT_EQ(errorOf([] { parse("a 1;\n  }"); }), "testDict:2:3: error: '}' has no matching '{'");
    EXPECT_EQ(errorOf([] { parse("a {\n b 1;"); }), "testDict:1:3: error: dictionary 'testDict/a' opened by '{' is never closed by '}'");
    EXPECT_EQ(errorOf([] { parse("a (1 2;"); }), "testDict:1:7: error: found ';' inside the list opened at line 1; is a ')' missing?");
    EXPECT_EQ(errorOf([] { parse("a 1 2);"); }), "testDict:1:6: error: ')' has no matching '('");
    EXPECT_EQ(errorOf([] { parse("a 1; /* open"); }), "testDict:1:6: error: comment '/*' is never closed by '*/'");
    EXPECT_EQ(errorOf([] { parse("s \"open\n;"); }), "testDict:1:3: error: string is not closed by '\"' on the same line");
    EXPECT_EQ(errorOf([] { parse("3 4;"); }), "testDict:1:1: error: expected a keyword, found number 3");
    EXPECT_EQ(errorOf([] { parse("#includ \"x\";"); }),
              "testDict:1:1: error: unknown directive '#includ' (valid: #include, #includeParameters, and #eval in a value)");
    EXPECT_EQ(errorOf([] { parse("a $missing;"); }),
              "testDict:1:3: error: macro '$missing' refers to no entry defined before it in this or an enclosing dictionary");
    EXPECT_EQ(errorOf([] { parse("a ;"); }), "testDict:1:1: error: entry 'a' has no value before ';'");
}

TEST(Dictionary, MissingIncludeNamesTheDirective) {
    const std::string message = errorOf([] { parse("#include \"nowhere\""); });
    EXPECT_NE(message.find("testDict:1:10: error: #include \"nowhere\": error: cannot open dictionary"), std::string::npos) << message;
    EXPECT_NE(message.find("file not found"), std::string::npos) << message;
}

TEST(Dictionary, MissingFileIsAnError) {
    const std::string message = errorOf([] { Dictionary::fromFile("/nonexistent/controlDict"); });
    EXPECT_EQ(message, "error: cannot open dictionary '/nonexistent/controlDict': file not found");
}

TEST(Dictionary, IntegerOutOfRangeIsAnError) {
    // Found by the fuzzer: 1e308 read as an integer was converted before its range was checked.
    const Dictionary d = parse("big 1e308; small -3e9; limit 2147483647;");
    EXPECT_EQ(errorOf([&] { d.get<int>("big"); }),
              "testDict:1:5: error: keyword 'big' in dictionary 'testDict': expected an integer, found number 1e308");
    EXPECT_EQ(errorOf([&] { d.get<int>("small"); }),
              "testDict:1:18: error: keyword 'small' in dictionary 'testDict': expected an integer, found number -3e9");
    EXPECT_EQ(d.get<int>("limit"), 2147483647);
}

TEST(Dictionary, ListSizePrefixOutOfRangeIsAnError) {
    // Found by the fuzzer: a size prefix of 1e308 was converted to size_t before the comparison.
    const Dictionary d = parse("big 1e308(0 1); negative -1(0 1); good 2(0 1);");
    EXPECT_EQ(errorOf([&] { d.get<std::vector<double>>("big"); }), "testDict:1:5: error: keyword 'big': list size 1e308 does not match its 2 items");
    EXPECT_EQ(errorOf([&] { d.get<std::vector<double>>("negative"); }),
              "testDict:1:26: error: keyword 'negative': list size -1 does not match its 2 items");
    EXPECT_EQ(d.get<std::vector<double>>("good"), (std::vector<double>{0.0, 1.0}));
}

TEST(Dictionary, DeviceIsNotADictionary) {
    EXPECT_EQ(errorOf([] { Dictionary::fromFile("/dev/zero"); }), "error: cannot open dictionary '/dev/zero': not a regular file");
}

TEST(Dictionary, TypeErrorsSayWhatWasExpectedAndFound) {
    const Dictionary d = parse("inner { endTime abc; n 1.5; flag maybe; v (1 x); d { } w 3; many 1 2; neg -1; }");
    const Dictionary& in = d.subDict("inner");
    EXPECT_EQ(errorOf([&] { in.get<double>("endTime"); }),
              "testDict:1:17: error: keyword 'endTime' in dictionary 'testDict/inner': expected a number, found word 'abc'");
    EXPECT_EQ(errorOf([&] { in.get<int>("n"); }),
              "testDict:1:24: error: keyword 'n' in dictionary 'testDict/inner': expected an integer, found number 1.5");
    EXPECT_EQ(
        errorOf([&] { in.get<bool>("flag"); }),
        "testDict:1:34: error: keyword 'flag' in dictionary 'testDict/inner': expected a switch (yes/no, true/false, on/off), found word 'maybe'");
    EXPECT_EQ(errorOf([&] { in.get<std::vector<double>>("v"); }),
              "testDict:1:46: error: keyword 'v' in dictionary 'testDict/inner': expected a number, found word 'x'");
    EXPECT_EQ(errorOf([&] { in.get<double>("d"); }),
              "testDict:1:50: error: keyword 'd' in dictionary 'testDict/inner': expected a number, found a dictionary");
    EXPECT_EQ(errorOf([&] { in.get<std::string>("w"); }),
              "testDict:1:58: error: keyword 'w' in dictionary 'testDict/inner': expected a word, found number 3");
    EXPECT_EQ(errorOf([&] { in.get<double>("many"); }),
              "testDict:1:68: error: keyword 'many' in dictionary 'testDict/inner': expected a number, found '1 2'");
    EXPECT_EQ(errorOf([&] { in.getPositive("neg"); }),
              "testDict:1:71: error: keyword 'neg' in dictionary 'testDict/inner': must be greater than zero, found -1");
    EXPECT_EQ(errorOf([&] { in.getVector<3>("v"); }),
              "testDict:1:46: error: keyword 'v' in dictionary 'testDict/inner': expected a number, found word 'x'");
    EXPECT_EQ(errorOf([&] { in.subDict("w"); }),
              "testDict:1:56: error: 'w' in dictionary 'testDict/inner' must be a dictionary { ... }, found the value '3'");
}

TEST(Dictionary, MissingKeywordNamesTheDictionary) {
    const Dictionary d = parse("kernel\n{\n    hdx 1.3;\n}");
    EXPECT_EQ(errorOf([&] { d.subDict("kernel").get<std::string>("type"); }),
              "testDict:2:1: error: keyword 'type' is missing from dictionary 'testDict/kernel'");
}

TEST(Dictionary, ParameterFilesServeMacrosWithoutBecomingEntries) {
    // One parameter file for every dictionary of a case: what a dictionary does not use is no error.
    const auto dir = sph::test::freshDirectory();
    sph::test::writeFile(dir / "caseParameters", "H 0.6; dx #eval \"$H / 40\"; unusedHere 7;");
    sph::test::writeFile(dir / "system" / "dict",
                         "#includeParameters \"../caseParameters\"\n"
                         "depth $H; spacing $dx; length #eval \"5.366 * $H\";\n"
                         "H 0.5; own $H; sub { inner $dx; }\n");
    const Dictionary d = Dictionary::fromFile(dir / "system" / "dict");
    EXPECT_DOUBLE_EQ(d.get<double>("depth"), 0.6);
    EXPECT_DOUBLE_EQ(d.get<double>("spacing"), 0.015);
    EXPECT_DOUBLE_EQ(d.get<double>("length"), 5.366 * 0.6);
    EXPECT_DOUBLE_EQ(d.get<double>("own"), 0.5);  // the dictionary's own entry before the parameter
    EXPECT_DOUBLE_EQ(d.subDict("sub").get<double>("inner"), 0.015);
    d.get<double>("H");
    EXPECT_FALSE(d.found("unusedHere"));
    EXPECT_EQ(errorOf([&] { d.checkUnused(); }), "");
    // Opened inside a sub-dictionary, the parameters end with it.
    sph::test::writeFile(dir / "scoped", "sub { #includeParameters \"caseParameters\" a $H; }\nb $H;\n");
    EXPECT_EQ(errorOf([&] { Dictionary::fromFile(dir / "scoped"); }),
              (dir / "scoped").string() + ":2:3: error: macro '$H' refers to no entry defined before it in this or an enclosing dictionary");
    EXPECT_EQ(errorOf([] { parse("#includeParameters \"nowhere\""); }).substr(0, 70),
              "testDict:1:20: error: #includeParameters \"nowhere\": error: cannot open");
}

TEST(Dictionary, UnusedKeywordsAreReported) {
    const Dictionary d = parse("FoamFile { version 2; }\nendTime 1;\nendTme 2;\nsub { used 1; typo 2; }\n");
    d.get<double>("endTime");
    d.subDict("sub").get<double>("used");
    const std::string message = errorOf([&] { d.checkUnused(); });
    EXPECT_NE(message.find("testDict:3:1: 'endTme' in dictionary 'testDict'"), std::string::npos) << message;
    EXPECT_NE(message.find("testDict:4:15: 'typo' in dictionary 'testDict/sub'"), std::string::npos) << message;
    EXPECT_EQ(message.find("FoamFile"), std::string::npos) << message;
}

TEST(Dictionary, MisspeltKeywordsSayWhatWasMeant) {
    // An unused entry names the keyword asked for and not found that it nearly spells.
    const Dictionary d = parse("endTime 1;\ncourrant 0.2;\nInterval 3;\nwriteFormat binary;\n");
    d.get<double>("endTime");
    d.getOrDefault("courant", 0.1);
    d.getOrDefault("writeInterval", 0.1);
    const std::string message = errorOf([&] { d.checkUnused(); });
    EXPECT_NE(message.find("testDict:2:1: 'courrant' in dictionary 'testDict' (did you mean 'courant'?)"), std::string::npos) << message;
    EXPECT_NE(message.find("testDict:3:1: 'Interval' in dictionary 'testDict'\n"), std::string::npos) << "too far from writeInterval: " << message;
    EXPECT_NE(message.find("'writeFormat' in dictionary 'testDict'"), std::string::npos) << message;
    EXPECT_EQ(message.find("'writeFormat' in dictionary 'testDict' (did you mean"), std::string::npos) << message;
    // A missing keyword names the unused entry that nearly spells it.
    const Dictionary e = parse("endTme 1;\nrho0 1000;\n");
    e.get<double>("rho0");
    EXPECT_EQ(errorOf([&] { e.get<double>("endTime"); }),
              "testDict: error: keyword 'endTime' is missing from dictionary 'testDict' (is 'endTme' at testDict:1:1 misspelt?)");
}

TEST(Dictionary, DeepNestingIsAnErrorNotAStackOverflow) {
    // 20,000 levels crashed the recursive parser (SIGSEGV); 100 is far beyond any case.
    std::string deep;
    for (int i = 0; i < 20000; ++i) deep += "a { ";
    EXPECT_EQ(errorOf([&] { parse(deep); }), "testDict:1:403: error: dictionaries nested more than 100 deep");
    std::string fine;
    for (int i = 0; i < 100; ++i) fine += "a { ";
    fine += "x 1;";
    for (int i = 0; i < 100; ++i) fine += " }";
    EXPECT_NO_THROW(parse(fine));
}

TEST(Dictionary, DoublingMacrosStopAtTheTokenLimit) {
    // Each level copies the one before twice: 2^60 tokens if nothing stopped it.
    std::string text = "m0 (1 2);";
    for (int i = 1; i <= 60; ++i) text += " m" + std::to_string(i) + " ($m" + std::to_string(i - 1) + " $m" + std::to_string(i - 1) + ");";
    EXPECT_NE(errorOf([&] { parse(text); }).find("error: the dictionary expands to more than 2000000 tokens"), std::string::npos);
    std::string dictionaries = "d0 { x 1; }";
    for (int i = 1; i <= 60; ++i)
        dictionaries += " d" + std::to_string(i) + " { a $d" + std::to_string(i - 1) + "; b $d" + std::to_string(i - 1) + "; }";
    EXPECT_NE(errorOf([&] { parse(dictionaries); }).find("error: the dictionary expands to more than 2000000 tokens"), std::string::npos);
}

TEST(Dictionary, NumberOutsideTheDoubleRangeIsAnError) {
    // 1e400 was read as infinity and blamed later on whatever it produced.
    EXPECT_EQ(errorOf([] { parse("rho0 1e400;"); }),
              "testDict:1:6: error: number 1e400 is outside the range of a double (magnitudes 2.2e-308 to 1.8e308, or 0)");
    EXPECT_NE(errorOf([] { parse("a -1e400;"); }), "");
    EXPECT_NE(errorOf([] { parse("a 1e-400;"); }), "");
    EXPECT_DOUBLE_EQ(parse("a 1e300; b 0; c 0e-5;").get<double>("a"), 1e300);
}

TEST(Dictionary, MacroThatReplacesItsOwnSourceWhileMerging) {
    // Found by the fuzzer (heap-use-after-free): merging `$type` replaced the entry `type` it
    // was being read from.
    const Dictionary d = parse("d { type { type 1; other 2; } $type }");
    EXPECT_DOUBLE_EQ(d.subDict("d").get<double>("type"), 1.0);
    EXPECT_DOUBLE_EQ(d.subDict("d").get<double>("other"), 2.0);
}

TEST(Dictionary, EvalComputesArithmeticOverMacros) {
    const Dictionary d = parse(
        "H 0.6; dx 0.02; sub { n 3; }\n"
        "length #eval \"5.366 * $H\";\n"
        "box (0 #eval \"${H} / 2 + ${sub/n}\" 1);\n"
        "r0 #eval \"$dx/2\"; c0 #eval \"10 * sqrt(9.81 * $H)\";\n"
        "phase #eval \"pi / 2\"; square #eval \"(-$dx)^2\"; wet #eval \"$H > 0.5 ? 1 : 0\";\n"
        "twice #eval \"2 * $length\";");
    EXPECT_DOUBLE_EQ(d.get<double>("length"), 5.366 * 0.6);
    EXPECT_EQ(d.get<std::vector<double>>("box"), (std::vector<double>{0, 0.6 / 2 + 3, 1}));
    EXPECT_DOUBLE_EQ(d.get<double>("r0"), 0.01);
    EXPECT_DOUBLE_EQ(d.get<double>("c0"), 10 * std::sqrt(9.81 * 0.6));
    EXPECT_DOUBLE_EQ(d.get<double>("phase"), M_PI / 2);
    EXPECT_DOUBLE_EQ(d.get<double>("square"), 0.0004);  // the macro's sign kept: (-(0.02))^2
    EXPECT_DOUBLE_EQ(d.get<double>("wet"), 1.0);
    EXPECT_EQ(d.get<double>("twice"), 2 * (5.366 * 0.6));  // an evaluated number reads back exactly
}

TEST(Dictionary, EvalErrorsNameTheExpressionAndWhatIsWrong) {
    EXPECT_EQ(errorOf([] { parse("a #eval \"2 *\";"); }), "testDict:1:9: error: #eval \"2 *\": Unexpected end of expression at position 4");
    EXPECT_EQ(errorOf([] { parse("a #eval 2;"); }),
              "testDict:1:3: error: #eval must be followed by an expression in double quotes, as in: length #eval \"2 * $H\";");
    EXPECT_EQ(errorOf([] { parse("#eval \"1\";"); }),
              "testDict:1:1: error: #eval gives a value and stands after a keyword, as in: length #eval \"2 * $H\";");
    EXPECT_EQ(errorOf([] { parse("a #eval \"$H + 1\";"); }),
              "testDict:1:9: error: macro '$H' refers to no entry defined before it in this or an enclosing dictionary");
    EXPECT_EQ(errorOf([] { parse("v (1 2); a #eval \"$v + 1\";"); }),
              "testDict:1:18: error: #eval \"$v + 1\": macro '$v' must name one number; it names 4 tokens");
    EXPECT_EQ(errorOf([] { parse("w abc; a #eval \"$w\";"); }),
              "testDict:1:16: error: #eval \"$w\": macro '$w' must name one number; it names word 'abc'");
    EXPECT_EQ(errorOf([] { parse("a #eval \"1 / 0\";"); }), "testDict:1:9: error: #eval \"1 / 0\" is infinite (a division by zero?)");
    EXPECT_EQ(errorOf([] { parse("a #eval \"sqrt(-1)\";"); }),
              "testDict:1:9: error: #eval \"sqrt(-1)\" is not a number (a square root or logarithm of a negative?)");
    EXPECT_EQ(errorOf([] { parse("a #eval \"1, 2\";"); }), "testDict:1:9: error: #eval \"1, 2\": 2 comma-separated values; #eval gives one number");
    EXPECT_EQ(errorOf([] { parse("a #eval \"${H\";"); }), "testDict:1:9: error: #eval \"${H\": '${' is never closed by '}'");
    // muParser takes up to 20000 characters; the message shows a long expression by its start.
    EXPECT_EQ(errorOf([] { parse("a #eval \"" + std::string(10001, '(') + "1" + std::string(10001, ')') + "\";"); }),
              "testDict:1:9: error: #eval \"" + std::string(60, '(') + "...\": Expression too long.");
    EXPECT_DOUBLE_EQ(parse("a #eval \"" + std::string(2000, '(') + "1" + std::string(2000, ')') + "\";").get<double>("a"), 1.0);
}
