// SPDX-License-Identifier: Apache-2.0
// The board's UART link (UART0 on GPIO0 TX / GPIO1 RX, 8N1 at kUartBaud,
// FIFOs off so the PL011 interrupts once per byte each way) and the
// MeasurementFeed built on it, as on the Cortex-M boards: the interrupt
// fills an RX ring and drains a TX ring; board::RingFeed turns the RX ring
// into frames, board::RingTrackSink pushes KTRK records into the TX ring.
#pragma once

#include <cstdint>

#include "board_config.hpp"
#include "kestrel/board/ring_feed.hpp"
#include "kestrel/hal/ring_buffer.hpp"

namespace kestrel::m0plus {

using RxRing = hal::ByteRingBuffer<kRxRingBytes>;
using TxRing = hal::ByteRingBuffer<kTxRingBytes>;

RxRing& uart0_rx_ring();
TxRing& uart0_tx_ring();

/// Reset release, pins, baud rate and receive interrupt of UART0. Call once
/// after configure_clocks(), with the clk_peri it left (core_clock_hz():
/// kPeriHz, kXoscHz or kRoscNominalHz; the divisors are precomputed for
/// those three). Returns false, with UART0 left untouched, if UART0 does
/// not leave reset within the bound.
[[nodiscard]] bool uart0_start(std::uint32_t peri_hz);

/// Unmask the TX interrupt so the ISR drains the transmit ring (an atomic
/// set through the RP2040's register alias: no race with the ISR's clear).
void uart0_kick_tx();

/// Receive-side line errors counted by the ISR since start.
struct UartLineErrors {
  std::uint32_t overrun;  ///< Bytes lost because the receiver was full.
  std::uint32_t framing;  ///< Stop bit missing (byte kept; the frame CRC decides).
};
[[nodiscard]] UartLineErrors uart0_line_errors();

using UartRingFeed = board::RingFeed<RxRing, kAssemblerBytes>;

}  // namespace kestrel::m0plus
