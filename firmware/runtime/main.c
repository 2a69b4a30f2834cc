/* The monitor: reads the window's commands, places each command's buffers where it asks, calls
 * the kernel through the checked-call trampoline, and writes the results back into the window. */
#include <stdint.h>

#include "bvb/dma.h"
#include "bvb/mailbox.h"
#include "registry.h"
#include "runtime.h"

extern uint8_t _sdram_arena_start[], _sdram_arena_end[];
extern uint8_t _l1a_arena_start[], _l1a_arena_end[];
extern uint8_t _l1b_arena_start[], _l1b_arena_end[];
extern uint8_t _scratch_arena_start[], _scratch_arena_end[];

struct arena {
  uint8_t *start, *end, *next;
};

static struct arena arenas[BVB_PLACE_WINDOW];

static uint32_t registry_hash(void) {
  uint32_t h = 2166136261u;
  for (uint32_t k = 0; k < bvb_kernel_count; ++k) {
    const char *p = bvb_kernels[k].name;
    do {
      h ^= (uint8_t)*p;
      h *= 16777619u;
    } while (*p++);
  }
  return h;
}

static void reset_arenas(void) {
  arenas[BVB_PLACE_SDRAM] = (struct arena){_sdram_arena_start, _sdram_arena_end, _sdram_arena_start};
  arenas[BVB_PLACE_L1A] = (struct arena){_l1a_arena_start, _l1a_arena_end, _l1a_arena_start};
  arenas[BVB_PLACE_L1B] = (struct arena){_l1b_arena_start, _l1b_arena_end, _l1b_arena_start};
  arenas[BVB_PLACE_SCRATCH] =
      (struct arena){_scratch_arena_start, _scratch_arena_end, _scratch_arena_start};
}

static int valid_buffer(const struct bvb_buffer *b, uint32_t window_size) {
  if (b->place >= BVB_PLACE_COUNT || (b->guard & 3) || b->align < 4 || (b->align & (b->align - 1)) ||
      b->skew >= b->align)
    return 0;
  uint32_t span = b->size + 2 * b->guard;
  if (b->size > window_size || b->guard > window_size || span > window_size) return 0;
  return b->offset <= window_size - span;
}

/* Returns the data address for buffer b, or 0 when its memory is full. *tail is how many
 * bytes of its trailing guard band exist: all of them, except at the end of SDRAM. */
static uint8_t *place_buffer(const struct bvb_buffer *b, uint8_t *window, uint32_t *tail) {
  *tail = b->guard;
  if (b->place == BVB_PLACE_WINDOW) return window + b->offset + b->guard;
  if (b->place == BVB_PLACE_SDRAM_END) {
    /* From the top of the SDRAM arena down: the data ends where SDRAM does (what align and
     * skew leave of a gap is all of its trailing guard band), and the arena ends below it. */
    struct arena *a = &arenas[BVB_PLACE_SDRAM];
    const uintptr_t top = (uintptr_t)a->end;
    if ((uintptr_t)b->size + b->guard + b->align > top - (uintptr_t)a->next) return 0;
    const uintptr_t data = ((top - b->size - b->skew) & ~(uintptr_t)(b->align - 1)) + b->skew;
    const uint32_t gap = (uint32_t)(top - (data + b->size));
    if (gap < b->guard) *tail = gap;
    a->end = (uint8_t *)(data - b->guard);
    return (uint8_t *)data;
  }
  struct arena *a = &arenas[b->place];
  uintptr_t data = ((uintptr_t)a->next + b->guard + b->align - 1) & ~(uintptr_t)(b->align - 1);
  data += b->skew;
  uintptr_t end = data + b->size + b->guard;
  if (end > (uintptr_t)a->end || end < data) return 0;
  a->next = (uint8_t *)end;
  return (uint8_t *)data;
}

/* An argument the kernel does not take (R0-R2 or a stack slot beyond its count): junk like the
 * other caller-saved registers (call.S), so a kernel that reads one shows it. */
static uint32_t junk_arg(uint32_t seed, uint32_t i) {
  return seed ? (seed ^ 0x6A09E667u) * (2 * i + 1) + (i << 24) : 0;
}

static void run_command(struct bvb_command *c, uint8_t *window, uint32_t window_size,
                        uint32_t null_cycles) {
  static struct bvb_call call;
  uint8_t *addr[BVB_MAX_BUFS];
  uint32_t tail[BVB_MAX_BUFS];

  c->status = BVB_BAD_COMMAND;
  if (c->kernel >= bvb_kernel_count) { c->detail = BVB_BAD_KERNEL; return; }
  if (c->impl >= BVB_IMPL_COUNT) { c->detail = BVB_BAD_IMPL; return; }
  if (c->nargs > BVB_MAX_ARGS) { c->detail = BVB_BAD_NARGS; return; }
  if (c->nbufs > BVB_MAX_BUFS) { c->detail = BVB_BAD_NBUFS; return; }
  for (uint32_t i = 0; i < c->nbufs; ++i)
    if (!valid_buffer(&c->bufs[i], window_size)) { c->detail = BVB_BAD_BUFFER; return; }
  for (uint32_t i = 0; i < c->nargs; ++i)
    if ((c->argbuf >> i & 1) && c->args[i] >= c->nbufs) { c->detail = BVB_BAD_ARGBUF; return; }
  void (*fn)(void) = bvb_kernels[c->kernel].entry[c->impl];
  if (!fn) { c->status = BVB_NO_IMPL; return; }

  reset_arenas();
  for (uint32_t i = 0; i < c->nbufs; ++i) {
    const struct bvb_buffer *b = &c->bufs[i];
    addr[i] = place_buffer(b, window, &tail[i]);
    if (!addr[i]) { c->status = BVB_NO_SPACE; c->detail = i; return; }
    if (b->place != BVB_PLACE_WINDOW)
      memcpy(addr[i] - b->guard, window + b->offset, b->guard + b->size + tail[i]);
    c->buf_addr[i] = (uint32_t)(uintptr_t)addr[i];
  }

  memset(&call, 0, sizeof call);
  call.fn = fn;
  for (uint32_t i = 0; i < BVB_MAX_ARGS; ++i)
    call.args[i] = i >= c->nargs ? junk_arg(c->junk_seed, i) : (c->argbuf >> i & 1) ? (uint32_t)(uintptr_t)addr[c->args[i]] : c->args[i];
  call.limit = c->cycle_limit ? c->cycle_limit : BVB_DEFAULT_CYCLE_LIMIT;
  uint32_t status = bvb_call(&call, c->junk_seed, c->canary_seed);
  /* A kernel abandoned mid-transfer (fault, watchdog) may leave memory DMA running into the
   * buffers copied back below or into the next call: stop it. */
  bvb_dma_reset();

  for (uint32_t i = 0; i < c->nbufs; ++i) {
    const struct bvb_buffer *b = &c->bufs[i];
    if (b->place != BVB_PLACE_WINDOW)
      memcpy(window + b->offset, addr[i] - b->guard, b->guard + b->size + tail[i]);
  }
  c->cycles = call.cycles > null_cycles ? call.cycles - null_cycles : 0;
  c->ret = call.ret;
  c->abi_bad = call.abi_bad;
  /* GCC's hardware loops leave LC counting when a loop is left by an early exit (the C of
   * harris_select does), and its code always enters a loop through its LSETUP: for compiled
   * code, which runs from SDRAM, that is its convention, not a fault. The hand-written
   * assembly in L1 instruction SRAM is held to the stricter rule. */
  if ((uintptr_t)fn < L1_CODE_START) c->abi_bad &= ~(uint32_t)(BVB_ABI_LOOP0 | BVB_ABI_LOOP1);
  c->fault_seqstat = call.seqstat;
  c->fault_pc = call.pc;
  c->fault_addr = call.addr;
  c->status = status;
}

int main(void) {
  uint8_t *window = (uint8_t *)BVB_WINDOW_ADDR;
  struct bvb_header *h = (struct bvb_header *)window;

  h->registry_count = bvb_kernel_count;
  h->registry_hash = registry_hash();
  if (h->magic != BVB_MAGIC || h->version != BVB_VERSION || h->window_size > BVB_WINDOW_MAX ||
      h->ncommands > (h->window_size - sizeof *h) / sizeof(struct bvb_command)) {
    h->state = BVB_FW_BAD_HEADER;
    return 1;
  }
  h->state = BVB_FW_RUNNING;

  static struct bvb_call null_call;
  null_call.fn = bvb_null;
  null_call.limit = 100000;
  bvb_call(&null_call, 0, 0);
  h->null_call_cycles = null_call.cycles;

  struct bvb_command *cmds = (struct bvb_command *)(h + 1);
  volatile struct bvb_header *vh = h; /* the host writes it while we run */
  for (;;) {
    /* The request these commands answer, read before running them: a request the host makes
     * after seeing them served is then never mistaken for this one. */
    const uint32_t request = vh->request;
    for (uint32_t i = vh->first; i < vh->ncommands; ++i) {
      vh->current = i;
      run_command(&cmds[i], window, h->window_size, null_call.cycles);
    }
    vh->state = BVB_FW_DONE;
    if (!(vh->flags & BVB_SERVE)) return 0;
    vh->served = request;
    while (vh->request == request) {
    }
    __asm__ volatile("" ::: "memory"); /* commands and buffers changed under us */
    if (vh->request == BVB_STOP) return 0;
    if (vh->ncommands > (h->window_size - sizeof *h) / sizeof(struct bvb_command)) {
      vh->state = BVB_FW_BAD_HEADER;
      return 1;
    }
    vh->state = BVB_FW_RUNNING;
  }
}
