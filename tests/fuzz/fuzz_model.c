/* libFuzzer harness: the whole load-and-solve path on arbitrary bytes. The model is
 * parsed from memory; valid models (within a size limit) are solved with small
 * iteration budgets by every method, and their results turned into JSON; errors must
 * come back as status codes with messages. Any crash, hang, leak or sanitizer report
 * is a bug. Models with force densities (q=, force=) are form-found too, and the found
 * model solved. Build: make fuzz (clang). */
#include "catena.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* 1 if the JSON text parses and holds no null (cJSON's rendering of NaN/Inf). */
static int valid_json(const cJSON *j)
{
    if (!j || cJSON_IsNull(j)) return 0;
    for (const cJSON *c = j->child; c; c = c->next)
        if (!valid_json(c)) return 0;
    return 1;
}

/* Bound the work a fuzz input may ask for (steps x substeps x iterations): a valid
 * model asking for 1e5 substeps is slow, not a bug. */
static int affordable(const ctn_model *m)
{
    long sub = 0;
    for (size_t k = 0; k < ctn_model_step_count(m); k++) {
        int n = ctn_model_step_substeps(m, k);
        sub += n > 0 ? n : 8;
    }
    return sub <= 64;
}

static void solve_all(ctn_ctx *ctx, const ctn_model *m, const ctn_solve_options *file_opt)
{
    if (!affordable(m)) return;
    for (int method = 0; method < 3; method++) {
        ctn_solve_options opt;
        ctn_solution *s = NULL;
        opt = *file_opt;
        opt.method = (ctn_method)method;
        if (opt.maxit > 25) opt.maxit = 25;
        if (opt.steps > 8) opt.steps = 8;
        if (opt.arcsteps > 25) opt.arcsteps = 25;
        if (opt.maxcuts > 4 || opt.maxcuts < 0) opt.maxcuts = 4;
        if (opt.dynamics.t_end > 200 * opt.dynamics.dt) opt.dynamics.t_end = 200 * opt.dynamics.dt;   /* a run of */
        if (opt.dynamics.maxit > 25) opt.dynamics.maxit = 25;                /* 200 steps at most */
        if (opt.dynamics.maxcuts > 4) opt.dynamics.maxcuts = 4;
        if (ctn_solve(ctx, m, &opt, &s) == CTN_OK) {
            char *json = NULL;
            if (ctn_result_json(ctx, m, s, 0, &json) == CTN_OK) {
                cJSON *j = cJSON_Parse(json);
                if (!valid_json(j)) __builtin_trap(); /* invalid JSON or a NaN in it */
                cJSON_Delete(j);
            }
            ctn_json_free(json);
        } else if (!*ctn_ctx_message(ctx)) {
            __builtin_trap();                         /* an error without a message */
        }
        ctn_solution_destroy(&s);
    }
}

/* Models with force densities: form finding (a short budget), then the found model
 * solved; an error has a message, a found model holds no NaN. */
static void formfind(ctn_ctx *ctx, ctn_model *m, const ctn_solve_options *file_opt)
{
    if (!ctn_model_force_density_count(m)) return;
    ctn_formfind_options o;
    ctn_formfind_report rep;
    ctn_formfind_options_init(&o);
    o.maxit = 50;
    if (ctn_formfind(ctx, m, &o, &rep) != CTN_OK) {
        if (!*ctn_ctx_message(ctx)) __builtin_trap();
        return;
    }
    for (size_t i = 0; i < ctn_model_node_count(m) && rep.reason == CTN_FF_CONVERGED; i++) {
        ctn_node_info p;
        ctn_model_node(m, i, &p);
        if (!isfinite(p.X[0] + p.X[1] + p.X[2])) __builtin_trap();
    }
    if (rep.reason == CTN_FF_CONVERGED) solve_all(ctx, m, file_opt);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ctn_ctx *ctx = NULL;
    ctn_model *m = NULL;
    if (ctn_ctx_create(&ctx)) return 0;
    ctn_ctx_set_model_limit(ctx, 2000);
    ctn_solve_options opt;
    int rc = ctn_read_string(ctx, "fuzz.cable", (const char *)data, size, &m, &opt);
    if (rc == CTN_OK) solve_all(ctx, m, &opt);
    if (rc == CTN_OK) formfind(ctx, m, &opt);
    else if (!*ctn_ctx_message(ctx)) __builtin_trap();
    ctn_model_destroy(&m);
    ctn_ctx_destroy(&ctx);
    return 0;
}
