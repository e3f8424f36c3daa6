/* src/core's last error and logger (core/log.h), the one error channel of every layer: each
 * message reaches the logger as one line (a newline inside, from a path, a driver or a parser,
 * becomes a space) and is the object's last error; a long one is cut, never overflowed. */
#include <stdio.h>
#include <string.h>

#include "core/log.h"
#include "tl_test.h"

typedef struct lines {
    int count, multiline;
    tl_log_level level;
    char last[2048];
} lines;

static void keep(void *user, tl_log_level level, const char *message)
{
    lines *l = user;
    l->count++;
    l->level = level;
    if (strchr(message, '\n') || strchr(message, '\r')) l->multiline++;
    snprintf(l->last, sizeof l->last, "%s", message);
}

TL_TEST(core_log_one_line_per_message)
{
    lines l = {0};
    tl__log log = {.logger = {keep, &l}};
    TL_CHECK(tl__log_fail(&log, TL_ERROR_IO, "%s: %s", "a\nb.png", "no such file\r\n") == TL_ERROR_IO);
    TL_CHECK(l.count == 1 && l.multiline == 0 && l.level == TL_LOG_ERROR);
    printf("object: '%s'\n", l.last);
    TL_CHECK(strcmp(l.last, "a b.png: no such file") == 0 && strcmp(log.last_error, l.last) == 0);
    tl__log_message(&log, TL_LOG_WARNING, "two\nlines");
    TL_CHECK(l.count == 2 && l.multiline == 0 && l.level == TL_LOG_WARNING && strcmp(l.last, "two lines") == 0);
    TL_CHECK(strcmp(log.last_error, "a b.png: no such file") == 0); /* a warning is not a failure */
    tl_logger logger = {keep, &l};
    TL_CHECK(tl__logger_fail(&logger, TL_ERROR_PARSE, "x\ny") == TL_ERROR_PARSE);
    TL_CHECK(l.count == 3 && l.multiline == 0 && l.level == TL_LOG_ERROR && strcmp(l.last, "x y") == 0);
    tl__logger_message(&logger, TL_LOG_INFO, "\nz\n");
    TL_CHECK(l.count == 4 && l.multiline == 0 && l.level == TL_LOG_INFO && strcmp(l.last, " z") == 0);
    /* no logger: silent, and the object still keeps its last error */
    tl__log quiet = {0};
    TL_CHECK(tl__log_fail(&quiet, TL_ERROR_GL, "kept\n") == TL_ERROR_GL && strcmp(quiet.last_error, "kept") == 0);
    TL_CHECK(tl__logger_fail(NULL, TL_ERROR_LIMIT, "nobody") == TL_ERROR_LIMIT);
    tl__logger_message(NULL, TL_LOG_WARNING, "nobody");
    TL_CHECK(l.count == 4);
}

TL_TEST(core_log_long_message_cut_to_its_buffer)
{
    static char big[3 * TL__LOG_MESSAGE_SIZE];
    memset(big, 'x', sizeof big - 1);
    lines l = {0};
    tl__log log = {.logger = {keep, &l}};
    tl__log_fail(&log, TL_ERROR_LIMIT, "%s", big);
    TL_CHECK(strlen(log.last_error) == TL__LOG_MESSAGE_SIZE - 1 && strcmp(l.last, log.last_error) == 0);
}
