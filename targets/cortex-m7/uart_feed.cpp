// SPDX-License-Identifier: Apache-2.0
// USART3 driver of the STM32H743 (registers, interrupt handler, both rings).
// See uart_feed.hpp for the data path. Differs from the F4's USART in its
// register layout (ISR/ICR/RDR/TDR) and in that error flags must be cleared
// through ICR.
#include "uart_feed.hpp"

#include <atomic>

#include "registers.hpp"

namespace kestrel::m7 {
namespace {

// Constant-initialised (constexpr constructors), so they sit in .bss and
// are usable before any static constructor runs.
constinit RxRing g_rx_ring{};
constinit TxRing g_tx_ring{};

// Written by the ISR only; relaxed is enough for counters read for diagnostics.
constinit std::atomic<std::uint32_t> g_overruns{0};
constinit std::atomic<std::uint32_t> g_framing_errors{0};
constinit std::atomic<std::uint32_t> g_noise_errors{0};

void count(std::atomic<std::uint32_t>& counter) {
  counter.store(counter.load(std::memory_order_relaxed) + 1u, std::memory_order_relaxed);
}

// BRR with OVER8 = 0 and PRESC = 0 holds f_ker / baud, rounded to nearest.
// 100 MHz / 115200 -> 868 (0.01 % error); on the HSI fallback 64 MHz ->
// 556 (0.08 %).
constexpr std::uint32_t brr(std::uint32_t apb1_hz) { return (apb1_hz + kUartBaud / 2) / kUartBaud; }
static_assert(brr(kApb1Hz) >= 16 && brr(kApb1Hz) <= 0xFFFF, "USART3: baud rate out of range for its kernel clock");
static_assert(brr(kHsiHz) >= 16 && brr(kHsiHz) <= 0xFFFF, "USART3: baud rate out of range on the HSI");

constexpr std::uint32_t kNvicPriority = 0x80;  // mid priority (upper 4 bits are implemented)

}  // namespace

RxRing& usart3_rx_ring() { return g_rx_ring; }
TxRing& usart3_tx_ring() { return g_tx_ring; }

void usart3_start(std::uint32_t apb1_hz) {
  using namespace regs;
  reg(kRccAhb4enr) |= kRccAhb4enrGpiodEn;
  reg(kRccApb1lenr) |= kRccApb1lenrUsart3En;
  // A read-back after a clock enable: the peripheral is clocked before the
  // first access below.
  [[maybe_unused]] const std::uint32_t settle = reg(kRccApb1lenr);

  // PD8 (TX) and PD9 (RX): alternate function 7, high speed, pull-up on RX so
  // an unconnected line idles high instead of producing framing errors.
  reg(kGpiodAfrh) = (reg(kGpiodAfrh) & ~0xFFu) | 0x77u;
  reg(kGpiodOspeedr) = (reg(kGpiodOspeedr) & ~(0xFu << 16)) | (0xAu << 16);
  reg(kGpiodPupdr) = (reg(kGpiodPupdr) & ~(0xFu << 16)) | (0x4u << 16);
  reg(kGpiodModer) = (reg(kGpiodModer) & ~(0xFu << 16)) | (0xAu << 16);

  reg(kUsart3Cr1) = 0;  // disabled while configuring; 8 data bits, no parity, FIFO off
  reg(kUsart3Cr2) = 0;  // 1 stop bit
  reg(kUsart3Cr3) = 0;  // no flow control, no DMA
  reg(kUsart3Brr) = brr(apb1_hz);
  reg(kUsart3Cr1) = kUsartCr1Ue | kUsartCr1Te | kUsartCr1Re | kUsartCr1Rxneie;

  reinterpret_cast<volatile std::uint8_t*>(kNvicIpr0)[kUsart3Irq] = kNvicPriority;
  reg(kNvicIser0 + 4 * (kUsart3Irq / 32)) = 1u << (kUsart3Irq % 32);
}

void usart3_kick_tx() {
  // Read-modify-write from the main loop; the ISR may clear TXEIE in
  // between, in which case this sets it again and the ISR takes one extra
  // TXE interrupt, finds the ring empty (or not) and behaves correctly.
  regs::reg(regs::kUsart3Cr1) |= regs::kUsartCr1Txeie;
}

UartLineErrors usart3_line_errors() {
  return {g_overruns.load(std::memory_order_relaxed), g_framing_errors.load(std::memory_order_relaxed),
          g_noise_errors.load(std::memory_order_relaxed)};
}

}  // namespace kestrel::m7

/// USART3 global interrupt: RXNE -> receive ring (ORE/NE/FE counted and
/// cleared through ICR); TXE -> next byte of the transmit ring, or TXEIE off
/// when it is empty. Bounded: one byte each way per entry.
extern "C" void USART3_IRQHandler() {
  using namespace kestrel::m7;
  using namespace kestrel::m7::regs;
  const std::uint32_t isr = reg(kUsart3Isr);
  const std::uint32_t errors = isr & (kUsartIsrOre | kUsartIsrNe | kUsartIsrFe);
  if (errors != 0) {
    if ((isr & kUsartIsrOre) != 0) count(g_overruns);
    if ((isr & kUsartIsrFe) != 0) count(g_framing_errors);
    if ((isr & kUsartIsrNe) != 0) count(g_noise_errors);
    reg(kUsart3Icr) = kUsartIcrOrecf | kUsartIcrNecf | kUsartIcrFecf;
  }
  if ((isr & kUsartIsrRxne) != 0) {
    const auto byte = static_cast<std::uint8_t>(reg(kUsart3Rdr) & 0xFFu);  // reading RDR clears RXNE
    // A full ring drops the byte and counts it (ByteRingBuffer::overflow_count).
    (void)g_rx_ring.push(byte);
  }
  const std::uint32_t cr1 = reg(kUsart3Cr1);
  if ((cr1 & kUsartCr1Txeie) != 0 && (isr & kUsartIsrTxe) != 0) {
    std::uint8_t byte = 0;
    if (g_tx_ring.pop(byte)) {
      reg(kUsart3Tdr) = byte;
    } else {
      reg(kUsart3Cr1) = cr1 & ~kUsartCr1Txeie;
    }
  }
}
