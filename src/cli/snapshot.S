/* snapshot.S — carries the shipped catalogue's snapshot (written at build
 * time by catsnap, see input/catalog_snap.h) in the program's read-only
 * data, between the two symbols main() hands to cli_use_snapshot().
 * `.incbin` finds catalog.snap on the assembler's include path (-I). */
	.section .rodata
	.balign 16
	.globl aeroeval_snapshot
	.globl aeroeval_snapshot_end
aeroeval_snapshot:
	.incbin "catalog.snap"
aeroeval_snapshot_end:
	.section .note.GNU-stack,"",@progbits
