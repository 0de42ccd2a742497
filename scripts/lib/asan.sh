# Sourced by scripts/test_asan.sh and scripts/fuzz.sh: the one sanitized build both lanes share.
# build-asan/ with clang, AddressSanitizer and UndefinedBehaviorSanitizer at -O1 (CGAL's
# translation units dominate the build; -O0 would make the suite several times slower, -O2 the
# build; line tables are all a sanitizer's stack trace needs, full -g cost 8% more build), and the
# libFuzzer targets (INSULA_FUZZ: the layers also get coverage instrumentation).
asan_build=build-asan
configure_asan() {  # extra cmake arguments...
  CC=clang CXX=clang++ cmake -S . -B $asan_build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" -DINSULA_SANITIZE=ON \
    -DINSULA_FUZZ=ON -DINSULA_BENCH=OFF "$@" >/dev/null
}
# Any report fails; tools/sanitizers/*.supp name the few reports that are CGAL's own, each with why.
supp="$PWD/tools/sanitizers"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$supp/ubsan.supp"
