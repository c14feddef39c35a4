// SPDX-License-Identifier: Apache-2.0
// The few STM32H743 and Cortex-M7 registers this board touches, as constexpr
// addresses with the reference-manual name, offset and the bits used. No
// vendor HAL or CMSIS is available, so this file is the register map; each
// block cites its source: RM0433 (STM32H742/743/750/753 reference manual)
// and the ARMv7-M Architecture Reference Manual (DDI 0403E) for the core,
// with the offsets cross-checked against ST's CMSIS device header
// (stm32h743xx.h) field layout. Access goes through reg(), a volatile 32-bit
// lvalue at an address.
#pragma once

#include <cstdint>

namespace kestrel::m7::regs {

using Address = std::uintptr_t;

/// The memory-mapped 32-bit register at `address`.
inline volatile std::uint32_t& reg(Address address) {
  return *reinterpret_cast<volatile std::uint32_t*>(address);
}

// ------------------------------------------------------------- Core (SCS) --

inline constexpr Address kScbVtor = 0xE000ED08;   ///< Vector table offset (ARMv7-M B3.2.5).
inline constexpr Address kScbAircr = 0xE000ED0C;  ///< Application interrupt and reset control (B3.2.6).
inline constexpr std::uint32_t kAircrVectKey = 0x05FAu << 16;   ///< Write key of AIRCR.
inline constexpr std::uint32_t kAircrSysResetReq = 1u << 2;     ///< Request a system reset.
inline constexpr Address kScbCcr = 0xE000ED14;    ///< Configuration and control (B3.2.8).
inline constexpr std::uint32_t kCcrDc = 1u << 16;  ///< L1 data cache enable (Cortex-M7).
inline constexpr std::uint32_t kCcrIc = 1u << 17;  ///< L1 instruction cache enable (Cortex-M7).
inline constexpr Address kScbCcsidr = 0xE000ED80;  ///< Cache size ID of the level CSSELR selects.
inline constexpr Address kScbCsselr = 0xE000ED84;  ///< Cache size selection: 0 = L1 data cache.
inline constexpr Address kScbCpacr = 0xE000ED88;   ///< Coprocessor access control (B3.2.20).
inline constexpr std::uint32_t kCpacrCp10Cp11Full = 0xFu << 20;  ///< CP10+CP11 (the FPU): full access.
inline constexpr Address kScbIciallu = 0xE000EF50;  ///< Invalidate all instruction caches to PoU.
inline constexpr Address kScbDcisw = 0xE000EF60;    ///< Invalidate data cache line by set/way.

inline constexpr Address kDhcsr = 0xE000EDF0;  ///< Debug halting control and status (C1.6.2).
inline constexpr std::uint32_t kDhcsrCDebugEn = 1u << 0;  ///< A debugger is attached.

/// NVIC (B3.4): set-enable registers ISER0.. and byte-wide priority registers.
inline constexpr Address kNvicIser0 = 0xE000E100;
inline constexpr Address kNvicIpr0 = 0xE000E400;

// ------------------------------------------------------- STM32H743 (RM0433) --

/// PWR, base 0x5802 4800 (RM0433 section 6.8).
inline constexpr Address kPwrBase = 0x58024800;
inline constexpr Address kPwrCsr1 = kPwrBase + 0x04;  ///< Control status 1.
inline constexpr std::uint32_t kPwrCsr1ActVosRdy = 1u << 13;  ///< VOS in ACTVOS is applied.
inline constexpr Address kPwrCr3 = kPwrBase + 0x0C;   ///< Control 3: supply configuration (write once).
inline constexpr std::uint32_t kPwrCr3Bypass = 1u << 0;
inline constexpr std::uint32_t kPwrCr3LdoEn = 1u << 1;  ///< Core supplied by the LDO (NUCLEO-H743ZI).
inline constexpr std::uint32_t kPwrCr3ScuEn = 1u << 2;  ///< Supply configuration update enable.
inline constexpr Address kPwrD3cr = kPwrBase + 0x18;  ///< D3 domain control: voltage scaling.
inline constexpr std::uint32_t kPwrD3crVosRdy = 1u << 13;
inline constexpr std::uint32_t kPwrD3crVosMask = 0x3u << 14;
inline constexpr std::uint32_t kPwrD3crVos1 = 0x3u << 14;  ///< Scale 1 (VOS[1:0] = 11).

/// RCC, base 0x5802 4400 (RM0433 section 8.7).
inline constexpr Address kRccBase = 0x58024400;
inline constexpr Address kRccCr = kRccBase + 0x00;  ///< Source control.
inline constexpr std::uint32_t kRccCrHsiRdy = 1u << 2;
inline constexpr std::uint32_t kRccCrPll1On = 1u << 24;
inline constexpr std::uint32_t kRccCrPll1Rdy = 1u << 25;
inline constexpr Address kRccCfgr = kRccBase + 0x10;  ///< Clock configuration: system clock switch.
inline constexpr std::uint32_t kRccCfgrSwMask = 0x7u;
inline constexpr std::uint32_t kRccCfgrSwHsi = 0x0u;
inline constexpr std::uint32_t kRccCfgrSwPll1 = 0x3u;
inline constexpr std::uint32_t kRccCfgrSwsMask = 0x7u << 3;
inline constexpr std::uint32_t kRccCfgrSwsPll1 = 0x3u << 3;
inline constexpr Address kRccD1cfgr = kRccBase + 0x18;  ///< D1 prescalers: D1CPRE, HPRE, D1PPRE.
inline constexpr std::uint32_t kRccD1cfgrHpreDiv2 = 0x8u << 0;    ///< hclk = sys_ck / 2.
inline constexpr std::uint32_t kRccD1cfgrD1ppreDiv2 = 0x4u << 4;  ///< APB3 = hclk / 2.
inline constexpr Address kRccD2cfgr = kRccBase + 0x1C;  ///< D2 prescalers: APB1, APB2.
inline constexpr std::uint32_t kRccD2cfgrD2ppre1Div2 = 0x4u << 4;  ///< APB1 = hclk / 2.
inline constexpr std::uint32_t kRccD2cfgrD2ppre2Div2 = 0x4u << 8;  ///< APB2 = hclk / 2.
inline constexpr Address kRccD3cfgr = kRccBase + 0x20;  ///< D3 prescaler: APB4.
inline constexpr std::uint32_t kRccD3cfgrD3ppreDiv2 = 0x4u << 4;   ///< APB4 = hclk / 2.
inline constexpr Address kRccPllckselr = kRccBase + 0x28;  ///< PLL source (bits 1:0) and DIVM1 (bits 9:4).
inline constexpr Address kRccPllcfgr = kRccBase + 0x2C;    ///< PLL input range, VCO range, output enables.
inline constexpr std::uint32_t kRccPllcfgrPll1FracEn = 1u << 0;
inline constexpr std::uint32_t kRccPllcfgrPll1VcoSel = 1u << 1;      ///< 0 = wide VCO range (192-960 MHz).
inline constexpr std::uint32_t kRccPllcfgrPll1RgeMask = 0x3u << 2;
inline constexpr std::uint32_t kRccPllcfgrPll1Rge8To16 = 0x3u << 2;  ///< PLL1 input 8-16 MHz.
inline constexpr std::uint32_t kRccPllcfgrDivP1En = 1u << 16;
inline constexpr Address kRccPll1divr = kRccBase + 0x30;  ///< PLL1 DIVN1 (8:0), DIVP1 (15:9), DIVQ1, DIVR1; each value - 1.
inline constexpr Address kRccAhb4enr = kRccBase + 0xE0;   ///< AHB4 clock enable (GPIOs).
inline constexpr std::uint32_t kRccAhb4enrGpiodEn = 1u << 3;
inline constexpr Address kRccApb1lenr = kRccBase + 0xE8;  ///< APB1 low clock enable.
inline constexpr std::uint32_t kRccApb1lenrUsart3En = 1u << 18;

/// Flash interface, base 0x5200 2000 (RM0433 section 4.9).
inline constexpr Address kFlashAcr = 0x52002000;  ///< Access control: read latency, programming delay.
inline constexpr std::uint32_t kFlashAcrLatencyMask = 0xFu;
inline constexpr std::uint32_t kFlashAcrWrHighFreqMask = 0x3u << 4;

/// GPIOD, base 0x5802 0C00 (RM0433 section 11.4). PD8 = USART3_TX, PD9 = USART3_RX (AF7).
inline constexpr Address kGpiodBase = 0x58020C00;
inline constexpr Address kGpiodModer = kGpiodBase + 0x00;    ///< 2 bits per pin; 0b10 = alternate function.
inline constexpr Address kGpiodOspeedr = kGpiodBase + 0x08;  ///< 2 bits per pin; 0b10 = high speed.
inline constexpr Address kGpiodPupdr = kGpiodBase + 0x0C;    ///< 2 bits per pin; 0b01 = pull-up.
inline constexpr Address kGpiodAfrh = kGpiodBase + 0x24;     ///< 4 bits per pin 8-15; AF7 = USART1-3.

/// USART3, base 0x4000 4800, on APB1 (RM0433 section 48.7). Kernel clock at
/// reset (RCC_D2CCIP2R.USART234578SEL = 0): APB1, kApb1Hz.
inline constexpr Address kUsart3Base = 0x40004800;
inline constexpr Address kUsart3Cr1 = kUsart3Base + 0x00;  ///< Control 1.
inline constexpr Address kUsart3Cr2 = kUsart3Base + 0x04;  ///< Control 2 (stop bits).
inline constexpr Address kUsart3Cr3 = kUsart3Base + 0x08;  ///< Control 3 (flow control, DMA, FIFO thresholds).
inline constexpr Address kUsart3Brr = kUsart3Base + 0x0C;  ///< Baud rate: f_ker / baud with OVER8 = 0.
inline constexpr Address kUsart3Isr = kUsart3Base + 0x1C;  ///< Interrupt and status.
inline constexpr Address kUsart3Icr = kUsart3Base + 0x20;  ///< Interrupt flag clear.
inline constexpr Address kUsart3Rdr = kUsart3Base + 0x24;  ///< Receive data.
inline constexpr Address kUsart3Tdr = kUsart3Base + 0x28;  ///< Transmit data.
inline constexpr std::uint32_t kUsartCr1Ue = 1u << 0;      ///< USART enable.
inline constexpr std::uint32_t kUsartCr1Re = 1u << 2;      ///< Receiver enable.
inline constexpr std::uint32_t kUsartCr1Te = 1u << 3;      ///< Transmitter enable.
inline constexpr std::uint32_t kUsartCr1Rxneie = 1u << 5;  ///< Interrupt on RXNE (and ORE).
inline constexpr std::uint32_t kUsartCr1Txeie = 1u << 7;   ///< Interrupt on TXE.
inline constexpr std::uint32_t kUsartIsrFe = 1u << 1;      ///< Framing error.
inline constexpr std::uint32_t kUsartIsrNe = 1u << 2;      ///< Noise detected.
inline constexpr std::uint32_t kUsartIsrOre = 1u << 3;     ///< Overrun: a byte arrived before RDR was read.
inline constexpr std::uint32_t kUsartIsrRxne = 1u << 5;    ///< RDR holds a received byte.
inline constexpr std::uint32_t kUsartIsrTxe = 1u << 7;     ///< TDR can take the next byte.
/// ICR: writing 1 clears the flag (on the H7, reading RDR clears RXNE only;
/// ORE, NE and FE stay set until cleared here, and a set ORE keeps the
/// interrupt pending).
inline constexpr std::uint32_t kUsartIcrFecf = 1u << 1;
inline constexpr std::uint32_t kUsartIcrNecf = 1u << 2;
inline constexpr std::uint32_t kUsartIcrOrecf = 1u << 3;
inline constexpr std::uint32_t kUsart3Irq = 39;  ///< USART3 global interrupt (RM0433 table 145).

/// Number of external interrupt vectors of the STM32H743 (RM0433 table 145: 0..149).
inline constexpr std::uint32_t kIrqCount = 150;

}  // namespace kestrel::m7::regs
