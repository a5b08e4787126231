/* startup.S: the reset path of the bare-metal RV32 example. Sets gp and sp, a trap
 * vector that halts, clears .bss, calls main, then exits with main's value through the
 * exit system call (ecall with a7 = 93, a0 = status: what riscv-vp's tiny32 takes with
 * --intercept-syscalls, and newlib/picolibc's number on RISC-V). A platform that does not
 * take the call traps, and the trap vector halts in wfi. */
  .section .text.start, "ax", @progbits
  .globl _start
_start:
  .option push
  .option norelax
  la gp, __global_pointer$
  .option pop
  la sp, __stack_top
  la t0, halt
  .option push
  .option arch, +zicsr  /* rv32imac names no CSR instructions in newer binutils */
  csrw mtvec, t0
  .option pop
  la t0, __bss_start
  la t1, __bss_end
1:
  bgeu t0, t1, 2f
  sw zero, 0(t0)
  addi t0, t0, 4
  j 1b
2:
  call main
  li a7, 93
  ecall
  .align 2
halt:
  wfi
  j halt
