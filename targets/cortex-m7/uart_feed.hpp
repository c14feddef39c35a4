// SPDX-License-Identifier: Apache-2.0
// The board's UART link (USART3 on PD8/PD9, 8N1 at kUartBaud: the ST-LINK
// virtual COM port of the NUCLEO-H743ZI) and the MeasurementFeed built on
// it. One interrupt handler serves both directions:
//   RX: every received byte goes into a hal::ByteRingBuffer (ISR producer,
//       main-loop consumer); the feed (board::RingFeed) moves the buffered
//       bytes into a hal::FrameAssembler and returns the next decoded frame.
//   TX: the track sink (uart_sink.hpp) pushes whole KTRK records into a
//       second ring and calls usart3_kick_tx(); the TXE interrupt drains it.
// Nothing here blocks: a full RX ring drops bytes (counted; the frame's CRC
// then fails and the assembler resynchronises), an empty one gives kNoData.
#pragma once

#include <cstdint>

#include "board_config.hpp"
#include "kestrel/board/ring_feed.hpp"
#include "kestrel/hal/ring_buffer.hpp"

namespace kestrel::m7 {

using RxRing = hal::ByteRingBuffer<kRxRingBytes>;
using TxRing = hal::ByteRingBuffer<kTxRingBytes>;

/// The USART3 receive ring (filled by USART3_IRQHandler).
RxRing& usart3_rx_ring();
/// The USART3 transmit ring (drained by USART3_IRQHandler).
TxRing& usart3_tx_ring();

/// Clocks, pins, baud rate and receive interrupt of USART3. Call once after
/// configure_clocks(), with the APB1 clock it left (apb1_clock_hz()).
void usart3_start(std::uint32_t apb1_hz);

/// Make sure the TXE interrupt is on so the ISR drains the transmit ring.
/// Call after pushing bytes; harmless when already sending.
void usart3_kick_tx();

/// Receive-side line errors counted by the ISR since start (each wraps at 2^32).
struct UartLineErrors {
  std::uint32_t overrun;  ///< A byte arrived before the previous one was read (lost).
  std::uint32_t framing;  ///< Stop bit missing (byte kept; the frame CRC decides).
  std::uint32_t noise;    ///< Noise flag on a received byte (byte kept).
};
[[nodiscard]] UartLineErrors usart3_line_errors();

/// MeasurementFeed over the USART3 receive ring: bytes -> FrameAssembler -> frames.
using UartRingFeed = board::RingFeed<RxRing, kAssemblerBytes>;

}  // namespace kestrel::m7
