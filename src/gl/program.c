/* Programs from embedded shader sources: a #version header, #define permutations and a tiny
 * #include expansion that hands glShaderSource a list of pieces (no copy, no allocation). */
#include <string.h>

#include "gl.h"
#include "msg.h"
#include "shader_table.h"

#define TL__MAX_PIECES 1024
#define TL__MAX_LINE_DIRECTIVES 128
#define TL__MAX_INCLUDE_DEPTH 8
#define TL__MAX_INCLUDED 64

const char *tl__shader_source(const char *name)
{
    if (!name) return NULL;
    for (size_t i = 0; i < tl__embedded_shader_count; i++)
        if (strcmp(tl__embedded_shaders[i].name, name) == 0) return tl__embedded_shaders[i].source;
    return NULL;
}

static const tl__embedded_shader *tl__shader_find_n(const char *name, size_t n, size_t *index)
{
    for (size_t i = 0; i < tl__embedded_shader_count; i++) {
        const char *s = tl__embedded_shaders[i].name;
        if (strlen(s) == n && memcmp(s, name, n) == 0) {
            *index = i;
            return &tl__embedded_shaders[i];
        }
    }
    return NULL;
}

/* The pieces of one stage's source. */
typedef struct tl__source_list {
    const GLchar *ptr[TL__MAX_PIECES];
    GLint len[TL__MAX_PIECES];
    size_t count;
    char lines[TL__MAX_LINE_DIRECTIVES][40]; /* storage for generated #line directives */
    size_t line_count;
    size_t included[TL__MAX_INCLUDED]; /* table indices already expanded (include once) */
    size_t included_count;
    char *log;
    size_t log_size;
} tl__source_list;

static tl_result tl__add(tl__source_list *s, const char *p, size_t n)
{
    if (n == 0) return TL_OK;
    if (s->count == TL__MAX_PIECES || n > 0x7fffffff) {
        tl__msg(s->log, s->log_size, "shader source has more than %d pieces (includes, defines)",
                TL__MAX_PIECES);
        return TL_ERROR_LIMIT;
    }
    s->ptr[s->count] = p;
    s->len[s->count] = (GLint)n;
    s->count++;
    return TL_OK;
}

static tl_result tl__add_line(tl__source_list *s, size_t line, size_t string_number)
{
    if (s->line_count == TL__MAX_LINE_DIRECTIVES) {
        tl__msg(s->log, s->log_size, "shader source needs more than %d #line directives",
                TL__MAX_LINE_DIRECTIVES);
        return TL_ERROR_LIMIT;
    }
    char *buf = s->lines[s->line_count++];
    int n = snprintf(buf, sizeof s->lines[0], "#line %zu %zu\n", line, string_number);
    return tl__add(s, buf, (size_t)n);
}

static bool tl__is_space(char c) { return c == ' ' || c == '\t'; }

/* If [p, end) is `word` followed by a non-identifier character, returns the position after it. */
static const char *tl__match_word(const char *p, const char *end, const char *word)
{
    size_t n = strlen(word);
    if ((size_t)(end - p) < n || memcmp(p, word, n) != 0) return NULL;
    p += n;
    if (p < end && (*p == '_' || (*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
                    (*p >= '0' && *p <= '9')))
        return NULL;
    return p;
}

typedef enum { TL__LINE_PLAIN, TL__LINE_VERSION, TL__LINE_INCLUDE, TL__LINE_BAD_INCLUDE } tl__line_kind;

/* Classifies the line [p, end); for includes, the quoted name goes to name and name_len. */
static tl__line_kind tl__classify(const char *p, const char *end, const char **name,
                                  size_t *name_len)
{
    while (p < end && tl__is_space(*p)) p++;
    if (p == end || *p != '#') return TL__LINE_PLAIN;
    p++;
    while (p < end && tl__is_space(*p)) p++;
    if (tl__match_word(p, end, "version")) return TL__LINE_VERSION;
    const char *q = tl__match_word(p, end, "include");
    if (!q) return TL__LINE_PLAIN;
    while (q < end && tl__is_space(*q)) q++;
    if (q == end || *q != '"') return TL__LINE_BAD_INCLUDE;
    const char *start = ++q;
    while (q < end && *q != '"') q++;
    if (q == end || q == start) return TL__LINE_BAD_INCLUDE;
    *name = start;
    *name_len = (size_t)(q - start);
    q++;
    while (q < end && (tl__is_space(*q) || *q == '\r')) q++;
    if (q < end && !(end - q >= 2 && q[0] == '/' && (q[1] == '/' || q[1] == '*')))
        return TL__LINE_BAD_INCLUDE;
    return TL__LINE_INCLUDE;
}

/* Appends `text` (file `file`, #line source-string `number`) with includes expanded. */
static tl_result tl__expand(tl__source_list *s, const char *file, const char *text, size_t number,
                            int depth)
{
    static const char newline[] = "\n";
    const char *piece = text, *p = text;
    size_t line = 1;
    tl_result r;
    while (*p) {
        const char *end = strchr(p, '\n');
        if (!end) end = p + strlen(p);
        const char *name = NULL;
        size_t name_len = 0;
        tl__line_kind kind = tl__classify(p, end, &name, &name_len);
        if (kind == TL__LINE_BAD_INCLUDE) {
            tl__msg(s->log, s->log_size, "%s:%zu: malformed #include (expected #include \"name\")",
                    file, line);
            return TL_ERROR_PARSE;
        }
        if (kind != TL__LINE_PLAIN) {
            if ((r = tl__add(s, piece, (size_t)(p - piece))) != TL_OK) return r;
            if (kind == TL__LINE_VERSION) {
                /* Keep the line count: an empty line in place of the directive. */
                if ((r = tl__add(s, newline, 1)) != TL_OK) return r;
            } else {
                size_t index = 0;
                const tl__embedded_shader *inc = tl__shader_find_n(name, name_len, &index);
                if (!inc) {
                    tl__msg(s->log, s->log_size,
                            "%s:%zu: #include \"%.*s\": no such file among the embedded shaders",
                            file, line, (int)name_len, name);
                    return TL_ERROR_PARSE;
                }
                bool seen = false;
                for (size_t i = 0; i < s->included_count; i++) seen |= s->included[i] == index;
                if (!seen) {
                    if (depth + 1 > TL__MAX_INCLUDE_DEPTH) {
                        tl__msg(s->log, s->log_size, "%s:%zu: #include nested deeper than %d",
                                file, line, TL__MAX_INCLUDE_DEPTH);
                        return TL_ERROR_LIMIT;
                    }
                    if (s->included_count == TL__MAX_INCLUDED) {
                        tl__msg(s->log, s->log_size, "%s:%zu: more than %d included files", file,
                                line, TL__MAX_INCLUDED);
                        return TL_ERROR_LIMIT;
                    }
                    s->included[s->included_count++] = index;
                    if ((r = tl__add_line(s, 1, index + 1)) != TL_OK) return r;
                    if ((r = tl__expand(s, inc->name, inc->source, index + 1, depth + 1)) != TL_OK)
                        return r;
                    if (inc->length > 0 && inc->source[inc->length - 1] != '\n' &&
                        (r = tl__add(s, newline, 1)) != TL_OK)
                        return r;
                }
                if ((r = tl__add_line(s, line + 1, number)) != TL_OK) return r;
            }
            piece = *end ? end + 1 : end;
        }
        if (!*end) break;
        p = end + 1;
        line++;
    }
    return tl__add(s, piece, strlen(piece));
}

/* "NAME", "NAME=VALUE" or "NAME VALUE" -> "#define NAME VALUE\n" as pieces. */
static tl_result tl__add_define(tl__source_list *s, const char *define)
{
    static const char prefix[] = "#define ", space[] = " ", newline[] = "\n";
    size_t n = define ? strcspn(define, "= \t") : 0;
    bool ident = n > 0 && !(define[0] >= '0' && define[0] <= '9');
    for (size_t i = 0; ident && i < n; i++) {
        char c = define[i];
        ident = c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    }
    if (!ident || strchr(define, '\n')) {
        tl__msg(s->log, s->log_size,
                "bad define \"%s\" (expected NAME, NAME=VALUE or NAME VALUE on one line)",
                define ? define : "(null)");
        return TL_ERROR_INVALID_ARGUMENT;
    }
    tl_result r;
    if ((r = tl__add(s, prefix, sizeof prefix - 1)) != TL_OK) return r;
    if ((r = tl__add(s, define, n)) != TL_OK) return r;
    if (define[n]) {
        if ((r = tl__add(s, space, 1)) != TL_OK) return r;
        if ((r = tl__add(s, define + n + 1, strlen(define + n + 1))) != TL_OK) return r;
    }
    return tl__add(s, newline, 1);
}

static const char *tl__stage_string(GLenum type)
{
    switch (type) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_FRAGMENT_SHADER: return "fragment";
    case GL_GEOMETRY_SHADER: return "geometry";
    case GL_TESS_CONTROL_SHADER: return "tess control";
    case GL_TESS_EVALUATION_SHADER: return "tess evaluation";
    case GL_COMPUTE_SHADER: return "compute";
    default: return NULL;
    }
}

/* Appends an info log (shader or program) to the caller's log. */
static void tl__append_info_log(const GladGLContext *gl, GLuint object, bool program, char *log,
                                size_t log_size)
{
    if (!log || log_size == 0) return;
    size_t used = strlen(log);
    if (used + 1 >= log_size) return;
    GLsizei written = 0;
    GLsizei room = (GLsizei)(log_size - used > 0x7fffffff ? 0x7fffffff : log_size - used);
    if (program)
        gl->GetProgramInfoLog(object, room, &written, log + used);
    else
        gl->GetShaderInfoLog(object, room, &written, log + used);
    log[used + (size_t)written] = '\0';
}

static bool tl__has_info_log(const GladGLContext *gl, GLuint object, bool program)
{
    GLint n = 0;
    if (program)
        gl->GetProgramiv(object, GL_INFO_LOG_LENGTH, &n);
    else
        gl->GetShaderiv(object, GL_INFO_LOG_LENGTH, &n);
    return n > 1;
}

/* Log header naming the stage and the #line source-string numbers it used. */
static void tl__append_stage_header(const tl__source_list *s, const char *what, const char *stage,
                                    const char *name, char *log, size_t log_size)
{
    tl__msg_append(log, log_size, "%s %s shader \"%s\" (source strings: 0 = %s", what, stage,
                   name, name);
    for (size_t i = 0; i < s->included_count; i++)
        tl__msg_append(log, log_size, ", %zu = %s", s->included[i] + 1,
                       tl__embedded_shaders[s->included[i]].name);
    tl__msg_append(log, log_size, "%s", "):\n");
}

/* Checks the descriptor; the number of stages on success, 0 (with a message) otherwise. */
static size_t tl__program_stage_count(const GladGLContext *gl, const tl__program_desc *desc,
                                      char *log, size_t log_size)
{
    if (!gl || !desc) {
        tl__msg(log, log_size, "tl__program_build: NULL %s", !gl ? "context" : "descriptor");
        return 0;
    }
    if (desc->define_count && !desc->defines) {
        tl__msg(log, log_size, "%s", "tl__program_build: define_count without defines");
        return 0;
    }
    size_t stage_count = 0;
    while (stage_count < TL__PROGRAM_MAX_STAGES && desc->stages[stage_count].type != 0)
        stage_count++;
    if (stage_count == 0)
        tl__msg(log, log_size, "program \"%s\": no shader stage", desc->label ? desc->label : "");
    return stage_count;
}

/* Expands stage i's source (version header, defines, #includes) into s and compiles it. */
static tl_result tl__compile_stage(const GladGLContext *gl, const tl__program_desc *desc, size_t i,
                                   tl__source_list *s, GLuint *out_shader)
{
    static const char header[] = "#version 450 core\n";
    const tl__shader_stage *st = &desc->stages[i];
    const char *stage = tl__stage_string(st->type);
    const char *name = st->name ? st->name : "(inline)";
    const char *text = st->source ? st->source : tl__shader_source(st->name);
    if (!stage) {
        tl__msg(s->log, s->log_size, "stage %zu (\"%s\"): unknown shader type 0x%x", i, name,
                (unsigned)st->type);
        return TL_ERROR_INVALID_ARGUMENT;
    }
    if (!text) {
        tl__msg(s->log, s->log_size, "%s shader \"%s\": not among the embedded shaders", stage,
                name);
        return TL_ERROR_INVALID_ARGUMENT;
    }
    s->count = s->line_count = s->included_count = 0;
    tl_result result = tl__add(s, header, sizeof header - 1);
    for (size_t d = 0; d < desc->define_count && result == TL_OK; d++)
        result = tl__add_define(s, desc->defines[d]);
    if (result == TL_OK) result = tl__add_line(s, 1, 0);
    if (result == TL_OK) result = tl__expand(s, name, text, 0, 0);
    if (result != TL_OK) return result;

    GLuint shader = gl->CreateShader(st->type);
    *out_shader = shader;
    if (!shader) {
        tl__msg(s->log, s->log_size, "%s shader \"%s\": glCreateShader failed", stage, name);
        return TL_ERROR_GL;
    }
    gl->ShaderSource(shader, (GLsizei)s->count, s->ptr, s->len);
    gl->CompileShader(shader);
    GLint ok = GL_FALSE;
    gl->GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok || tl__has_info_log(gl, shader, false)) {
        tl__append_stage_header(s, ok ? "warnings in" : "failed to compile", stage, name, s->log,
                                s->log_size);
        tl__append_info_log(gl, shader, false, s->log, s->log_size);
    }
    return ok ? TL_OK : TL_ERROR_GL;
}

/* Links the compiled stages into a new program; the shaders stay the caller's. */
static tl_result tl__link_program(const GladGLContext *gl, const tl__program_desc *desc,
                                  const GLuint *shaders, size_t stage_count, GLuint *out_program,
                                  char *log, size_t log_size)
{
    GLuint program = gl->CreateProgram();
    if (!program) {
        tl__msg_append(log, log_size, "%s", "glCreateProgram failed\n");
        return TL_ERROR_GL;
    }
    for (size_t i = 0; i < stage_count; i++) gl->AttachShader(program, shaders[i]);
    gl->LinkProgram(program);
    GLint ok = GL_FALSE;
    gl->GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok || tl__has_info_log(gl, program, true)) {
        tl__msg_append(log, log_size, "%s program \"%s\":\n", ok ? "link warnings in" : "failed to link",
                       desc->label ? desc->label : "");
        tl__append_info_log(gl, program, true, log, log_size);
    }
    for (size_t i = 0; i < stage_count; i++) gl->DetachShader(program, shaders[i]);
    if (!ok) {
        gl->DeleteProgram(program);
        return TL_ERROR_GL;
    }
    *out_program = program;
    return TL_OK;
}

tl_result tl__program_build(const GladGLContext *gl, const tl__program_desc *desc,
                            GLuint *out_program, char *log, size_t log_size)
{
    tl__msg(log, log_size, "%s", "");
    if (!out_program) {
        tl__msg(log, log_size, "%s", "tl__program_build: NULL output");
        return TL_ERROR_INVALID_ARGUMENT;
    }
    *out_program = 0;
    size_t stage_count = tl__program_stage_count(gl, desc, log, log_size);
    if (stage_count == 0) return TL_ERROR_INVALID_ARGUMENT;

    /* About 12 KiB on the stack keeps the call allocation-free. */
    tl__source_list list;
    list.log = log;
    list.log_size = log_size;
    GLuint shaders[TL__PROGRAM_MAX_STAGES] = {0};
    GLuint program = 0;
    tl_result result = TL_OK;
    for (size_t i = 0; i < stage_count && result == TL_OK; i++)
        result = tl__compile_stage(gl, desc, i, &list, &shaders[i]);
    if (result == TL_OK)
        result = tl__link_program(gl, desc, shaders, stage_count, &program, log, log_size);
    for (size_t i = 0; i < stage_count; i++)
        if (shaders[i]) gl->DeleteShader(shaders[i]);
    if (result != TL_OK) return result;
    tl__gl_label(gl, GL_PROGRAM, program, desc->label);
    *out_program = program;
    return TL_OK;
}
