// The translation unit that builds the libraries' and programs' shared precompiled headers
// (top-level CMakeLists.txt, REFLOC_PCH); it has no code of its own.
