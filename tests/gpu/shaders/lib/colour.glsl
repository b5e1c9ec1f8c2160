// A snippet included by uses_include.frag.
vec4 test_colour() { return vec4(0.25, 0.5, 0.75, 1.0); }
