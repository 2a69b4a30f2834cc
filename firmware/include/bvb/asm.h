/* The frame of an assembly kernel under the C ABI, for the .S files (after #include).
 * Arguments 1-3 arrive in R0-R2, argument k >= 4 at [SP + 12 + 4 (k - 4)] on entry (the caller
 * leaves 12 bytes for R0-R2 below them); R4-R7, P3-P5, FP and SP are the caller's, L0-L3 are 0
 * on return, LC0/LC1 must not be left counting (the harness's ABI check catches each).
 *
 *   BVB_FUNC name[, section[, align]]
 *                             the global function _name in section: .l1.text (the default, L1
 *                             instruction SRAM: the loops) or .text (SDRAM through the
 *                             instruction cache: once-a-call code), aligned to `align` bytes
 *                             (4 unless given) and typed
 *   BVB_ENDFUNC name          its size
 *   BVB_ARG(k, pushed)        the offset from SP of argument k (1-based, k >= 4) once the
 *                             prologue has moved SP down by `pushed` bytes (saved registers,
 *                             RETS, FP, the outgoing argument space)
 *
 * A kernel names its stack arguments once, after its prologue, and reads them by name:
 *   #define PUSHED 16                     RETS and 12 bytes of outgoing argument space
 *   #define ARG_WIDTH BVB_ARG(4, PUSHED)
 *   r3 = [sp + ARG_WIDTH];
 * (firmware/asm/add_sat.S, the example kernel). */
#ifndef BVB_ASM_H
#define BVB_ASM_H

#define BVB_ARG(k, pushed) (12 + 4 * ((k) - 4) + (pushed))

#ifdef __ASSEMBLER__
.macro BVB_FUNC name, section=.l1.text, align=4
	.section \section, "ax"
	.align \align
	.global _\name
	.type _\name, STT_FUNC
_\name:
.endm

.macro BVB_ENDFUNC name
	.size _\name, . - _\name
.endm
#endif

#endif
