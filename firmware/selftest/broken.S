/* Broken twins of bvb_add_sat_u8_asm (and one of bvb_harris_nms_asm) whose defect needs
 * assembly: ABI breaks, faults, registers read without being set. The ones that compute
 * correctly run the real kernel before or after doing their damage, so only the damage differs.
 * Those that run code after the real kernel keep RETS (and what they need of the arguments) in
 * .Lsaved, off the stack, so the stack arguments stay where the real kernel looks for them. */
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

/* harris_nms returning one more candidate than it found (and wrote to *count). */
BROKEN(bvb_broken_wrong_return)
	p0.l = .Lsaved; p0.h = .Lsaved;
	r3 = rets;
	[p0] = r3;
	call _bvb_harris_nms_asm;
	p0.l = .Lsaved; p0.h = .Lsaved;
	r3 = [p0];
	rets = r3;
	r0 += 1;
	rts;

/* Loads the four bytes after its input a (a + (h - 1) * ss + w on), as a loop that fetches one
 * word ahead does, then computes correctly. Harmless inside the guard band; at the end of
 * SDRAM one of the loads faults. */
BROKEN(bvb_broken_read_past_end)
	[--sp] = r0;
	r0 = [sp + 4 + 16];	/* h */
	r0 += -1;
	r3 = [sp + 4 + 20];	/* ss */
	r0 *= r3;
	r3 = [sp + 4 + 12];	/* w */
	r0 = r0 + r3;
	r3 = [sp];		/* a */
	r0 = r0 + r3;
	p0 = r0;
	r0 = [sp++];
	r3 = b[p0++] (z);
	r3 = b[p0++] (z);
	r3 = b[p0++] (z);
	r3 = b[p0] (z);
	jump.l _bvb_add_sat_u8_asm;

/* Returns from inside a hardware loop: loop 1 still counts, its bottom in this code. */
BROKEN(bvb_broken_loop_armed)
	p0.l = .Lsaved; p0.h = .Lsaved;
	r3 = rets;
	[p0] = r3;
	call _bvb_add_sat_u8_asm;
	p1 = 3;
	lsetup (.Larm_top, .Larm_bottom) lc1 = p1;
.Larm_top:
	jump .Larm_out;
.Larm_bottom:
	nop;
.Larm_out:
	p0.l = .Lsaved; p0.h = .Lsaved;
	r3 = [p0];
	rets = r3;
	rts;

/* Redoes dst[0] = min(a[0] + b[0], 255) by multiply-accumulating into A1 without clearing it
 * first (a forgotten "A1 = 0"): right only while the caller happens to leave A1 zero. */
BROKEN(bvb_broken_uninit_a1)
	p0.l = .Lsaved; p0.h = .Lsaved;
	r3 = rets;
	[p0] = r3;
	[p0 + 4] = r0;
	[p0 + 8] = r1;
	[p0 + 12] = r2;
	call _bvb_add_sat_u8_asm;
	p0.l = .Lsaved; p0.h = .Lsaved;
	p1 = [p0 + 4];
	p2 = [p0 + 8];
	r0 = b[p1] (z);
	r2 = b[p2] (z);
	r1 = 1;
	a1 += r0.l * r1.l (is);
	r3 = (a1 += r2.l * r1.l) (is);
	r1 = 255;
	r3 = min (r3, r1);
	p1 = [p0 + 12];
	b[p1] = r3;
	r3 = [p0];
	rets = r3;
	rts;

	.section .l1.bss.a, "aw", @nobits
	.align 4
.Lsaved_rets:
	.space 4
.Lsaved:
	.space 16
