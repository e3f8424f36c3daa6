/* Test harness runner (the executable's main): `exe` runs every case, `exe NAME...` runs the
 * named ones, `exe --list` prints the names, one a line, followed by " full" for the cases of the
 * full tier (tl_add_test registers them with ctest and labels those `full`). */
#include "tl_test.h"

int tl_test_failures;

#define TL_TEST_MAX_CASES 512

static const tl_test_case *registry[TL_TEST_MAX_CASES];
static size_t registry_count, registry_dropped;

void tl_test_register(const tl_test_case *c)
{
    if (registry_count < TL_TEST_MAX_CASES)
        registry[registry_count++] = c;
    else
        registry_dropped++;
}

/* Constructors run in no promised order; source order is. */
static int by_source_position(const void *a, const void *b)
{
    const tl_test_case *x = *(const tl_test_case *const *)a, *y = *(const tl_test_case *const *)b;
    int f = strcmp(x->file, y->file);
    return f ? f : (x->line > y->line) - (x->line < y->line);
}

/* A case name given twice would make two ctest tests of one name. */
static int names_unique(void)
{
    int ok = 1;
    for (size_t i = 0; i < registry_count; i++)
        for (size_t j = i + 1; j < registry_count; j++)
            if (strcmp(registry[i]->name, registry[j]->name) == 0) {
                fprintf(stderr, "test case %s is defined twice (%s:%d, %s:%d)\n", registry[i]->name,
                        registry[i]->file, registry[i]->line, registry[j]->file, registry[j]->line);
                ok = 0;
            }
    return ok;
}

static int run_selected(int argc, char **argv)
{
    size_t ran = 0, failed = 0;
    for (size_t i = 0; i < registry_count; i++) {
        const tl_test_case *c = registry[i];
        int selected = argc < 2;
        for (int a = 1; a < argc && !selected; a++) selected = strcmp(argv[a], c->name) == 0;
        if (!selected) continue;
        int before = tl_test_failures;
        c->fn();
        ran++;
        if (tl_test_failures != before) {
            failed++;
            fprintf(stderr, "FAIL %s\n", c->name);
        } else {
            printf("ok   %s\n", c->name);
        }
    }
    if (ran == 0) {
        fprintf(stderr, "no test case matched\n");
        return 2;
    }
    return failed ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (registry_dropped) {
        fprintf(stderr, "more than %d test cases in one executable\n", TL_TEST_MAX_CASES);
        return 2;
    }
    qsort(registry, registry_count, sizeof registry[0], by_source_position);
    if (!names_unique()) return 2;
    if (argc == 2 && strcmp(argv[1], "--list") == 0) {
        for (size_t i = 0; i < registry_count; i++) printf("%s%s\n", registry[i]->name, registry[i]->full ? " full" : "");
        return 0;
    }
    return run_selected(argc, argv);
}
