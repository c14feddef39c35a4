// SPDX-License-Identifier: Apache-2.0
// The board's UART link (USART2 on PA2/PA3, 8N1 at kUartBaud) and the
// MeasurementFeed built on it. One interrupt handler serves both directions:
//   RX: every received byte goes into a hal::ByteRingBuffer (ISR producer,
//       main-loop consumer); UartRingFeed::poll() moves the buffered bytes
//       into a hal::FrameAssembler and returns the next decoded frame.
//   TX: the track sink (uart_sink.hpp) pushes whole report records into a
//       second ring and calls usart2_kick_tx(); the TXE interrupt drains it.
// Nothing here blocks: a full RX ring drops bytes (counted; the frame's CRC
// then fails and the assembler resynchronises), an empty one gives kNoData.
#pragma once

#include <cstdint>

#include "board_config.hpp"
#include "kestrel/board/ring_feed.hpp"
#include "kestrel/hal/ring_buffer.hpp"

namespace kestrel::m4f {

using RxRing = hal::ByteRingBuffer<kRxRingBytes>;
using TxRing = hal::ByteRingBuffer<kTxRingBytes>;

/// The USART2 receive ring (filled by USART2_IRQHandler).
RxRing& usart2_rx_ring();
/// The USART2 transmit ring (drained by USART2_IRQHandler).
TxRing& usart2_tx_ring();

/// Clock, pins, baud rate and receive interrupt of USART2. Call once after
/// configure_clocks(), with the APB1 clock it left (apb1_clock_hz()): the
/// baud divisor is computed from it, so the link keeps kUartBaud on the
/// HSI fallback too.
void usart2_start(std::uint32_t apb1_hz);

/// Make sure the TXE interrupt is on so the ISR drains the transmit ring.
/// Call after pushing bytes; harmless when already sending.
void usart2_kick_tx();

/// Main-loop companion of the TXE interrupt: while the transmit ring holds
/// bytes and the transmitter is empty, set the USART2 interrupt pending so
/// the ISR sends the next byte. On the STM32 the TXE interrupt is then
/// already pending and this is redundant (two register reads per call).
/// It is what moves the transmit ring under QEMU before 8.2, whose USART
/// model raises its interrupt for RXNE only (docs/porting.md, "Emulated
/// test"). The ISR stays the ring's only consumer. Call once per loop.
void usart2_poll_tx();

/// Receive-side line errors counted by the ISR since start (each wraps at 2^32).
struct UartLineErrors {
  std::uint32_t overrun;  ///< A byte arrived before the previous one was read (lost).
  std::uint32_t framing;  ///< Stop bit missing (byte kept; the frame CRC decides).
  std::uint32_t noise;    ///< Noise flag on a received byte (byte kept).
};
[[nodiscard]] UartLineErrors usart2_line_errors();

/// MeasurementFeed over the USART2 receive ring: bytes -> FrameAssembler
/// -> frames (targets/common/include/kestrel/board/ring_feed.hpp). poll()
/// never blocks; see RingFeed::poll for the statuses.
using UartRingFeed = board::RingFeed<RxRing, kAssemblerBytes>;

}  // namespace kestrel::m4f
