/*
 * cmocka.h - stands in for cmocka's header when configure did not find
 * cmocka: the library and zrcube build without it, and `make check`
 * stops here with what to do.
 */
#error "make check needs cmocka, which configure did not find: install it (Debian: apt-get install libcmocka-dev) and run configure again"
