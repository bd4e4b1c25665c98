/* replay.c — runs files through the fuzz target without libFuzzer (the regression inputs of
 * tests/fuzz_regressions/ in `make test`, built with the address and undefined-behaviour
 * sanitizers). Usage: fuzz_replay FILE...; exit status 0 when every file went through. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int main(int argc, char **argv) {
  for (int i = 1; i < argc; i++) {
    FILE *f = fopen(argv[i], "rb");
    if (!f) {
      perror(argv[i]);
      return 1;
    }
    static uint8_t buf[1 << 20];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    LLVMFuzzerTestOneInput(buf, n);
    printf("ok %s\n", argv[i]);
  }
  return 0;
}
