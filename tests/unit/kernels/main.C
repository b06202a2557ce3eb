// Test sources of this binary are listed in Make/files; gtest_main provides main().
