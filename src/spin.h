/* spin.h — waiting on another thread's store without sleeping.
 *
 * A solve's two threads hand each other work for a fraction of a
 * millisecond; a thread that sleeps on this kind of virtual machine takes
 * 35-100 us to wake, so the short waits spin.  Any module may include it.
 */
#ifndef AEROEVAL_SPIN_H
#define AEROEVAL_SPIN_H

/* One turn of a spin-wait loop: tells the CPU the loop is waiting. */
static inline void
spin_pause(void)
{
#if defined(__x86_64__) || defined(__i386__)
	__builtin_ia32_pause();
#elif defined(__aarch64__)
	__asm__ __volatile__("yield");
#endif
}

#endif
