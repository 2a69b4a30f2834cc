/* The memory-mapped window between the host harness and the firmware: the whole contract between
 * them, shared by both. All fields are little-endian 32-bit words; the host builds the window in a
 * file that the simulator maps at BVB_WINDOW_ADDR (--memory-mapfile), so what the firmware writes
 * there lands in the host's file.
 *
 * Layout: struct bvb_header, then header.ncommands struct bvb_command, then the data area holding
 * every buffer, each as [guard][data][guard]. A command names a kernel (its index in the registry,
 * firmware/kernels.def), an implementation, up to BVB_MAX_ARGS 32-bit arguments and up to
 * BVB_MAX_BUFS buffers. For each buffer the firmware copies guard+data+guard from the window into
 * the memory the command asks for (SDRAM, L1 data bank A/B, scratchpad, or the window itself),
 * passes the address of the data as the argument(s) that refer to it, calls the kernel through
 * the checked-call trampoline, then copies guard+data+guard back. The host checks data and guard
 * bands (a write outside a buffer shows in its guard band) and the result fields.
 *
 * The window is not part of the BF537's memory map: it sits in reserved address space, so no
 * firmware structure can alias it. */
#ifndef BVB_MAILBOX_H
#define BVB_MAILBOX_H


#define BVB_WINDOW_ADDR 0x30000000
/* 32 MB: eight 4 MB data CPLBs cover it, beside the eight that cover SDRAM (runtime/crt0.S). */
#define BVB_WINDOW_MAX (32 << 20)
#define BVB_MAGIC 0x31425642 /* "BVB1" */
#define BVB_VERSION 2
#define BVB_MAX_ARGS 12
#define BVB_MAX_BUFS 8

#ifndef __ASSEMBLER__
#include <stdint.h>

/* The BF537 memories a buffer can be placed in (addresses in firmware/runtime/link.ld). */
enum bvb_place {
  BVB_PLACE_SDRAM = 0,   /* 32 MB external SDRAM: frames */
  BVB_PLACE_L1A = 1,     /* L1 data bank A (16 KB SRAM; its upper 16 KB is data cache) */
  BVB_PLACE_L1B = 2,     /* L1 data bank B (24 KB usable; the stack takes the rest) */
  BVB_PLACE_SCRATCH = 3, /* L1 scratchpad (4 KB) */
  BVB_PLACE_WINDOW = 4,  /* in place, in the window: no copies (large runs) */
  /* SDRAM, its data ending at the end of SDRAM (as close as align and skew allow: less than
   * align bytes before it), with no guard band after it: nothing is mapped there, so a read or
   * write past the buffer's end faults (a data CPLB miss) and is blamed on the kernel. */
  BVB_PLACE_SDRAM_END = 5,
  BVB_PLACE_COUNT = 6
};

enum bvb_impl {
  BVB_IMPL_C = 0,   /* the C reference compiled for the Blackfin */
  BVB_IMPL_ASM = 1, /* the hand-written assembly */
  BVB_IMPL_COUNT
};

#endif

/* bvb_command.status (defines, not an enum: the assembly runtime uses them too) */
#define BVB_PENDING 0     /* not run (yet): the firmware stopped before it */
#define BVB_OK 1          /* ran and returned */
#define BVB_FAULT 2       /* an exception or hardware error inside the kernel */
#define BVB_HANG 3        /* ran past its cycle limit */
#define BVB_BAD_COMMAND 4 /* malformed command (see bvb_command.detail) */
#define BVB_NO_IMPL 5     /* the kernel has no such implementation */
#define BVB_NO_SPACE 6    /* buffers do not fit the memory they were placed in */

#ifndef __ASSEMBLER__
/* bvb_command.detail for BVB_BAD_COMMAND */
enum bvb_bad_command {
  BVB_BAD_KERNEL = 1,
  BVB_BAD_IMPL = 2,
  BVB_BAD_NARGS = 3,
  BVB_BAD_NBUFS = 4,
  BVB_BAD_BUFFER = 5, /* outside the window, or guard/alignment malformed */
  BVB_BAD_ARGBUF = 6, /* an argument names a buffer that does not exist */
  BVB_BAD_PLACE = 7
};

/* bvb_command.abi_bad bits: registers the kernel failed to preserve. */
enum bvb_abi_bits {
  BVB_ABI_R4 = 1u << 0, BVB_ABI_R5 = 1u << 1, BVB_ABI_R6 = 1u << 2, BVB_ABI_R7 = 1u << 3,
  BVB_ABI_P3 = 1u << 4, BVB_ABI_P4 = 1u << 5, BVB_ABI_P5 = 1u << 6, BVB_ABI_FP = 1u << 7,
  BVB_ABI_SP = 1u << 8,
  BVB_ABI_L0 = 1u << 9, BVB_ABI_L1 = 1u << 10, BVB_ABI_L2 = 1u << 11, BVB_ABI_L3 = 1u << 12,
  /* A hardware loop the kernel set up and left counting (LCn non-zero, LBn no longer the value
   * the caller put there): the caller's code passing its loop bottom would jump back. */
  BVB_ABI_LOOP0 = 1u << 13, BVB_ABI_LOOP1 = 1u << 14
};

struct bvb_buffer {
  uint32_t offset; /* window offset of the leading guard band */
  uint32_t size;   /* data bytes */
  uint32_t guard;  /* guard bytes on each side, a multiple of 4 */
  uint32_t place;  /* enum bvb_place */
  uint32_t align;  /* the data starts at a multiple of align (a power of two >= 4) ... */
  uint32_t skew;   /* ... plus skew bytes (0 <= skew < align), to test unaligned data */
};

struct bvb_command {
  /* written by the host */
  uint32_t kernel;      /* registry index */
  uint32_t impl;        /* enum bvb_impl */
  uint32_t cycle_limit; /* watchdog, in cycles; 0 = the default BVB_DEFAULT_CYCLE_LIMIT */
  uint32_t nargs;
  uint32_t nbufs;
  uint32_t argbuf;      /* bit i set: args[i] is a buffer index, passed as that buffer's address */
  uint32_t args[BVB_MAX_ARGS];
  struct bvb_buffer bufs[BVB_MAX_BUFS];
  /* written by the firmware */
  uint32_t status;      /* enum bvb_status */
  uint32_t detail;      /* enum bvb_bad_command, or the buffer index for BVB_NO_SPACE */
  uint32_t cycles;      /* cycles of the call, the empty call's overhead subtracted */
  uint32_t ret;         /* R0 on return */
  uint32_t abi_bad;     /* enum bvb_abi_bits */
  uint32_t fault_seqstat; /* SEQSTAT: EXCAUSE in bits 0-5, HWERRCAUSE in bits 14-18 */
  uint32_t fault_pc;    /* RETX (exception) or RETI (watchdog, hardware error) */
  uint32_t fault_addr;  /* DCPLB_FAULT_ADDR */
  uint32_t buf_addr[BVB_MAX_BUFS]; /* where each buffer's data was placed */
  /* written by the host */
  uint32_t junk_seed;   /* what the caller-saved registers hold on entry (runtime/call.S);
                           0: zero, arguments aside */
  uint32_t canary_seed; /* the callee-saved registers' canaries; 0: a fixed set */
  uint32_t reserved[2];
};

/* Serving: with BVB_SERVE in flags the firmware reads request, runs its commands, sets served to
 * the request it read, and polls request. The host, which maps the same file, rewrites commands and buffers in place
 * and bumps request; the firmware runs commands [first, ncommands) again. request = BVB_STOP
 * ends the run. One simulator process then serves a whole frame sequence, buffers the host does
 * not rewrite (a pipeline's state) staying in the window between frames. */
#define BVB_SERVE 1u
#define BVB_STOP 0xFFFFFFFFu

enum bvb_fw_state {
  BVB_FW_NOT_STARTED = 0,
  BVB_FW_RUNNING = 1,
  BVB_FW_DONE = 2,
  BVB_FW_BAD_HEADER = 3
};

struct bvb_header {
  /* written by the host */
  uint32_t magic;
  uint32_t version;
  uint32_t window_size;   /* bytes mapped */
  uint32_t ncommands;
  uint32_t first;         /* first command to run: lets the host resume after a crash */
  uint32_t flags;         /* BVB_SERVE: after the commands, wait for more (see below) */
  uint32_t request;       /* serving: the host bumps it when new commands are in place */
  uint32_t served;        /* serving: the firmware sets it to request when they are done */
  /* written by the firmware */
  uint32_t state;          /* enum bvb_fw_state */
  uint32_t current;        /* the command being run: the culprit if the simulator dies */
  uint32_t registry_count; /* the firmware's kernels, to catch a host/firmware mismatch */
  uint32_t registry_hash;  /* FNV-1a of the kernel names, each with its NUL */
  uint32_t null_call_cycles; /* an empty function through the trampoline: subtracted */
  /* A fault in the firmware itself, outside any kernel call (then the simulator exits 1). */
  uint32_t fatal_seqstat;
  uint32_t fatal_pc;
  uint32_t fatal_addr;
};

#endif /* __ASSEMBLER__ */

#define BVB_DEFAULT_CYCLE_LIMIT 2000000000u

/* Offsets the host relies on; a change here is a new BVB_VERSION. */
#ifdef __cplusplus
static_assert(sizeof(struct bvb_header) == 64, "bvb_header layout");
static_assert(sizeof(struct bvb_buffer) == 24, "bvb_buffer layout");
static_assert(sizeof(struct bvb_command) == 344, "bvb_command layout");
#endif

#endif
