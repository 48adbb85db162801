/* snapshot.S — carries the shipped catalogue's snapshot (written at build
 * time by catsnap, see input/catalog_snap.h) in the program's read-only
 * data: aeroeval_snapshot, and its length in bytes as a 64-bit number,
 * aeroeval_snapshot_bytes, which the assembler works out.  `.incbin` finds
 * catalog.snap on the assembler's include path (-I). */
	.section .rodata
	.balign 16
	.globl aeroeval_snapshot
aeroeval_snapshot:
	.incbin "catalog.snap"
snapshot_end:
	.balign 8
	.globl aeroeval_snapshot_bytes
aeroeval_snapshot_bytes:
	.quad snapshot_end - aeroeval_snapshot
	.section .note.GNU-stack,"",@progbits
