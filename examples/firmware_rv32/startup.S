/* startup.S: the reset path of the bare-metal RV32 example, and its trap entry.
 * _start sets gp and sp, points mtvec at trap_entry, clears .bss, calls main, then exits
 * with main's value through the exit system call (example_exit: ecall with a7 = 93,
 * a0 = status: what riscv-vp's tiny32 takes with --intercept-syscalls, and
 * newlib/picolibc's number on RISC-V). On a platform that does not take the call, the
 * ecall traps, example_trap skips it and the program halts in wfi. The console is the
 * write system call (a7 = 64, fd 1), taken the same way; a weak symbol, so that a build
 * with a UART replaces it. The CSR helpers the interrupt-driven build and the watchdog
 * use are here too, so that main.c stays plain C99. */
  .option push
  .option arch, +zicsr  /* newer binutils name no CSR instruction under rv32imac alone */

  .section .text.start, "ax", @progbits
  .globl _start
_start:
  .option push
  .option norelax
  la gp, __global_pointer$
  .option pop
  la sp, __stack_top
  la t0, trap_entry
  csrw mtvec, t0
  la t0, __bss_start
  la t1, __bss_end
1:
  bgeu t0, t1, 2f
  sw zero, 0(t0)
  addi t0, t0, 4
  j 1b
2:
  call main
  /* fall through to the exit call */

/* void example_exit(int status): the exit system call; halts if the platform does not
 * take it (the ecall came back). main's return, the watchdog and unexpected traps. */
  .globl example_exit
example_exit:
  li a7, 93
  ecall
  .globl example_halt
example_halt:
  csrci mstatus, 8
3:
  wfi
  j 3b

  .text
/* Every trap: the caller-saved registers kept, example_trap(mcause, mepc, mtval) called,
 * and mret to the address it returns (mepc itself, or past a faulting access it skips). */
  .align 2
trap_entry:
  addi sp, sp, -64
  sw ra, 0(sp)
  sw t0, 4(sp)
  sw t1, 8(sp)
  sw t2, 12(sp)
  sw a0, 16(sp)
  sw a1, 20(sp)
  sw a2, 24(sp)
  sw a3, 28(sp)
  sw a4, 32(sp)
  sw a5, 36(sp)
  sw a6, 40(sp)
  sw a7, 44(sp)
  sw t3, 48(sp)
  sw t4, 52(sp)
  sw t5, 56(sp)
  sw t6, 60(sp)
  csrr a0, mcause
  csrr a1, mepc
  csrr a2, mtval
  call example_trap
  csrw mepc, a0
  lw ra, 0(sp)
  lw t0, 4(sp)
  lw t1, 8(sp)
  lw t2, 12(sp)
  lw a0, 16(sp)
  lw a1, 20(sp)
  lw a2, 24(sp)
  lw a3, 28(sp)
  lw a4, 32(sp)
  lw a5, 36(sp)
  lw a6, 40(sp)
  lw a7, 44(sp)
  lw t3, 48(sp)
  lw t4, 52(sp)
  lw t5, 56(sp)
  lw t6, 60(sp)
  addi sp, sp, 64
  mret

/* void example_console_write(const char* text, size_t length): write(1, text, length). */
  .weak example_console_write
example_console_write:
  mv a2, a1
  mv a1, a0
  li a0, 1
  li a7, 64
  ecall
  ret

/* void example_interrupts_on(void): machine external interrupts on (mie.MEIE, mstatus.MIE). */
  .globl example_interrupts_on
example_interrupts_on:
  li t0, 0x800
  csrs mie, t0
  csrsi mstatus, 8
  ret

/* void example_timer_interrupt_on(void), _off(void): the machine timer interrupt
 * (mie.MTIE), which the watchdog's CLINT compare raises. */
  .globl example_timer_interrupt_on
example_timer_interrupt_on:
  li t0, 0x80
  csrs mie, t0
  ret
  .globl example_timer_interrupt_off
example_timer_interrupt_off:
  li t0, 0x80
  csrc mie, t0
  ret

/* void example_sleep_unless(volatile uint32_t* flag): wfi unless *flag is set, with
 * interrupts masked between the test and the wfi (wfi still wakes on a pending enabled
 * interrupt), so an interrupt that sets the flag just before cannot be slept through. */
  .globl example_sleep_unless
example_sleep_unless:
  csrci mstatus, 8
  lw t0, 0(a0)
  bnez t0, 4f
  wfi
4:
  csrsi mstatus, 8
  ret

  .option pop
