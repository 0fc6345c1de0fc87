// The source of the binary that builds the tests' shared precompiled header (tests/CMakeLists.txt);
// gtest_main gives it a main, and it runs no test.
