/* The example's operands, written once: main.c runs them on the IP, and the host program
 * expected/make_expected.cpp runs them on Core (the bit-accurate core) at build time to
 * write example_expected.h, the bits the firmware compares with. Plain C99 macros so that
 * both read them. */
#ifndef EXAMPLE_OPERANDS_H
#define EXAMPLE_OPERANDS_H

/* One operation with register 9: cos 64500/65536 (about 0.984), n 40, light (255, 200, 100). */
#define EXAMPLE_ONE_COS 64500u
#define EXAMPLE_ONE_N 40u
#define EXAMPLE_ONE_RGB {255u, 200u, 100u}

/* One highlight row through the batch windows: cos from 1.0 down to where the lobe is
 * clamped to 0 (about 0.76 for n 10), the same light. */
#define EXAMPLE_PIXELS 8u
#define EXAMPLE_ROW_COS {65536u, 65000u, 64000u, 62000u, 60000u, 57000u, 54000u, 50000u}
#define EXAMPLE_ROW_N 10u
#define EXAMPLE_ROW_RGB {255u, 200u, 100u}

#endif /* EXAMPLE_OPERANDS_H */
