// The line follower of samples/line_follower.sfc on an Arduino Uno: two IR line sensors and two
// DC motors on an L298N-style driver. gfec makes the engine (line_follower.c and .h) from the
// chart; this sketch is the robot library the chart's interface (samples/linebot.iface) asks
// for, and the loop that runs the engine every 10 ms, the chart's period.
// Wiring, build and upload: docs/tutorial-arduino.md.
#include "line_follower.h"

// The pins (docs/tutorial-arduino.md has them as a wiring table).
const uint8_t LEFT_IR = 2;    // left sensor's digital output
const uint8_t RIGHT_IR = 3;   // right sensor's digital output
const uint8_t LEFT_EN = 5;    // driver ENA
const uint8_t LEFT_IN1 = 7;   // driver IN1
const uint8_t LEFT_IN2 = 8;   // driver IN2
const uint8_t RIGHT_EN = 6;   // driver ENB
const uint8_t RIGHT_IN1 = 9;  // driver IN3
const uint8_t RIGHT_IN2 = 10; // driver IN4

// The level a sensor's output has over the black line: HIGH for the common TCRT5000 modules
// (black reflects no light). Sensors that read the other way: LOW.
const int IR_BLACK = HIGH;

// The chart's period (period 10ms in line_follower.sfc).
const unsigned long PERIOD_MS = 10;

static bool sees_black(uint8_t pin) { return digitalRead(pin) == IR_BLACK; }

// Forward: IN1 high, IN2 low, enabled. Stopped: everything low (the motor coasts).
static void drive(uint8_t en, uint8_t in1, uint8_t in2, bool forward) {
  digitalWrite(in1, forward ? HIGH : LOW);
  digitalWrite(in2, LOW);
  digitalWrite(en, forward ? HIGH : LOW);
}

// The robot library: the functions of interface LineBot. line_follower.h declares them
// extern "C" (the engine is C), so these definitions are the C functions the engine calls.
bool Left_IR_Black(void) { return sees_black(LEFT_IR); }
bool Left_IR_White(void) { return !sees_black(LEFT_IR); }
bool Right_IR_Black(void) { return sees_black(RIGHT_IR); }
bool Right_IR_White(void) { return !sees_black(RIGHT_IR); }
void Left_FW(void) { drive(LEFT_EN, LEFT_IN1, LEFT_IN2, true); }
void Left_Stop(void) { drive(LEFT_EN, LEFT_IN1, LEFT_IN2, false); }
void Right_FW(void) { drive(RIGHT_EN, RIGHT_IN1, RIGHT_IN2, true); }
void Right_Stop(void) { drive(RIGHT_EN, RIGHT_IN1, RIGHT_IN2, false); }

static LineFollower engine;
static unsigned long next_tick;

void setup() {
  pinMode(LEFT_IR, INPUT);
  pinMode(RIGHT_IR, INPUT);
  const uint8_t outputs[] = {LEFT_EN, LEFT_IN1, LEFT_IN2, RIGHT_EN, RIGHT_IN1, RIGHT_IN2};
  for (uint8_t pin : outputs) {
    digitalWrite(pin, LOW);
    pinMode(pin, OUTPUT);
  }
  LineFollower_init(&engine);
  next_tick = millis();  // the first tick at once
}

// One tick every PERIOD_MS, counted from the first: a late tick does not shift the ones after it.
void loop() {
  if ((long)(millis() - next_tick) >= 0) {
    next_tick += PERIOD_MS;
    LineFollower_run(&engine);
  }
}
