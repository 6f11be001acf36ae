#include "core/rng.h"

#include <math.h>
#include <string.h>

#include "core/hash.h"
#include "core/units.h"

/* Philox's multipliers and Weyl key increments (Salmon et al., SC'11, and
 * Random123's philox.h). */
#define PHILOX_M0 0xD2511F53u
#define PHILOX_M1 0xCD9E8D57u
#define PHILOX_W0 0x9E3779B9u
#define PHILOX_W1 0xBB67AE85u

/* One round: two 32x32 -> 64 products, their halves crossed with the other
 * words and the round key (a Feistel-like network). */
static void round4(uint32_t x[4], const uint32_t k[2])
{
    uint64_t p0 = (uint64_t)PHILOX_M0 * x[0];
    uint64_t p1 = (uint64_t)PHILOX_M1 * x[2];
    uint32_t y0 = (uint32_t)(p1 >> 32) ^ x[1] ^ k[0];
    uint32_t y1 = (uint32_t)p1;
    uint32_t y2 = (uint32_t)(p0 >> 32) ^ x[3] ^ k[1];
    uint32_t y3 = (uint32_t)p0;
    x[0] = y0;
    x[1] = y1;
    x[2] = y2;
    x[3] = y3;
}

void fw_philox4x32_10(const uint32_t ctr[4], const uint32_t key[2], uint32_t out[4])
{
    uint32_t x[4] = {ctr[0], ctr[1], ctr[2], ctr[3]};
    uint32_t k[2] = {key[0], key[1]};
    for (int r = 0; r < 10; r++) {
        if (r > 0) {
            k[0] += PHILOX_W0;
            k[1] += PHILOX_W1;
        }
        round4(x, k);
    }
    for (int i = 0; i < 4; i++)
        out[i] = x[i];
}

uint32_t fw_rng_vessel_key(const char *id)
{
    uint64_t h = fw_fnv1a(FW_FNV_INIT, id, strlen(id)); /* core/hash.h's FNV-1a, folded */
    uint32_t k = (uint32_t)(h ^ (h >> 32));
    return k ? k : 1u;
}

fw_rng fw_rng_make(uint64_t run_seed, uint32_t vessel, fw_purpose purpose)
{
    fw_rng s = {.key = {(uint32_t)run_seed, (uint32_t)(run_seed >> 32)},
                   .vessel = vessel,
                   .purpose = (uint32_t)purpose & 0x7fffffffu,
                   .counter = 0};
    return s;
}

fw_rng fw_rng_branch(const fw_rng *s, uint32_t branch)
{
    /* the purpose word's top bit marks a key derivation: no draw's block */
    uint32_t ctr[4] = {branch, 0, s->vessel, s->purpose | 0x80000000u}, out[4];
    fw_philox4x32_10(ctr, s->key, out);
    fw_rng b = *s;
    b.key[0] = out[0];
    b.key[1] = out[1];
    b.counter = 0;
    return b;
}

void fw_rng_block(fw_rng *s, uint64_t *a, uint64_t *b)
{
    uint32_t ctr[4] = {(uint32_t)s->counter, (uint32_t)(s->counter >> 32), s->vessel, s->purpose};
    uint32_t out[4];
    fw_philox4x32_10(ctr, s->key, out);
    s->counter++;
    *a = (uint64_t)out[0] | (uint64_t)out[1] << 32;
    *b = (uint64_t)out[2] | (uint64_t)out[3] << 32;
}

double fw_rng_uniform(fw_rng *s)
{
    uint64_t a, b;
    fw_rng_block(s, &a, &b);
    return (double)(a >> 11) * 0x1.0p-53;
}

double fw_rng_normal(fw_rng *s)
{
    uint64_t a, b;
    fw_rng_block(s, &a, &b);
    double u1 = (double)((a >> 11) + 1) * 0x1.0p-53; /* (0, 1]: ln never sees 0 */
    double u2 = (double)(b >> 11) * 0x1.0p-53;
    return sqrt(-2.0 * log(u1)) * cos(2.0 * FW_PI * u2);
}

double fw_rng_exponential(fw_rng *s)
{
    uint64_t a, b;
    fw_rng_block(s, &a, &b);
    return -log((double)((a >> 11) + 1) * 0x1.0p-53);
}
