/* Broken twins of bvb_add_sat_u8_asm whose defect needs assembly: ABI breaks and faults. The
 * ones that compute correctly jump to the real kernel after doing their damage, so only the
 * damage differs. */
	.section .l1.text, "ax"

#define BROKEN(name) .align 4; .global _##name; .type _##name, STT_FUNC; _##name:

BROKEN(bvb_broken_clobber_r4)
	r4 = 0;
	jump.l _bvb_add_sat_u8_asm;

BROKEN(bvb_broken_clobber_p5)
	p5 = 0;
	jump.l _bvb_add_sat_u8_asm;

BROKEN(bvb_broken_leave_l3)
	r3 = 4;
	l3 = r3;
	jump.l _bvb_add_sat_u8_asm;

/* Returns with SP 8 bytes lower. RETS is kept off the stack so the arguments stay put. */
BROKEN(bvb_broken_move_sp)
	p0.l = .Lsaved_rets; p0.h = .Lsaved_rets;
	r3 = rets;
	[p0] = r3;
	call _bvb_add_sat_u8_asm;
	p0.l = .Lsaved_rets; p0.h = .Lsaved_rets;
	r3 = [p0];
	rets = r3;
	sp += -8;
	rts;

BROKEN(bvb_broken_endless_loop)
1:	jump 1b;

BROKEN(bvb_broken_illegal_insn)
	.dd 0xffffffff;
	rts;

/* A 32-bit load from an address that is 3 mod 4, inside the first word of dst. */
BROKEN(bvb_broken_misaligned)
	bitset (r2, 0);
	bitset (r2, 1);
	p0 = r2;
	r0 = [p0];
	rts;

/* Reads past the board's 32 MB of SDRAM. */
BROKEN(bvb_broken_read_unmapped)
	p0.l = 0x0000; p0.h = 0x0800;
	r0 = [p0];
	rts;

/* Jumps into memory that holds no code. */
BROKEN(bvb_broken_wild_jump)
	p0.l = 0x0000; p0.h = 0x1000;
	jump (p0);

	.section .l1.bss.a, "aw", @nobits
	.align 4
.Lsaved_rets:
	.space 4
