// Included by every test file, with no include guard on purpose: the test
// programs compile as unity sources (tests/CMakeLists.txt), where CMake
// defines PLANET_TEST_ID to a name unique to each file, and each file keeps
// its helpers in `namespace { namespace PLANET_TEST_ID {`, so that the same
// helper names in two files do not clash. Compiled file by file, the name
// is empty and that inner namespace is one more anonymous one.
#ifndef PLANET_TEST_ID
#define PLANET_TEST_ID
#endif
