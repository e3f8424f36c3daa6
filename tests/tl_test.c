/* Test harness runner: `exe` runs every case, `exe NAME...` runs the named ones, `exe --list`
 * prints the names. */
#include "tl_test.h"

int tl_test_failures;

int tl_test_main(int argc, char **argv, const tl_test_case *cases, size_t count)
{
    if (argc == 2 && strcmp(argv[1], "--list") == 0) {
        for (size_t i = 0; i < count; i++) printf("%s\n", cases[i].name);
        return 0;
    }
    size_t ran = 0, failed = 0;
    for (size_t i = 0; i < count; i++) {
        int selected = argc < 2;
        for (int a = 1; a < argc && !selected; a++) selected = strcmp(argv[a], cases[i].name) == 0;
        if (!selected) continue;
        int before = tl_test_failures;
        cases[i].fn();
        ran++;
        if (tl_test_failures != before) {
            failed++;
            fprintf(stderr, "FAIL %s\n", cases[i].name);
        } else {
            printf("ok   %s\n", cases[i].name);
        }
    }
    if (ran == 0) {
        fprintf(stderr, "no test case matched\n");
        return 2;
    }
    return failed ? 1 : 0;
}
