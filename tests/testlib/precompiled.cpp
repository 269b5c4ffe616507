// The one source of uprog_test_pch, the target whose precompiled header (GoogleTest) every
// test executable reuses (tests/CMakeLists.txt); it defines nothing.
