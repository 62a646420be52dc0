// The one source of sphTestHeaders, the target that compiles the tests' shared precompiled
// header (tests/CMakeLists.txt); the tests reuse it, and this file adds no code.
