/* The line follower (samples/line_follower.sfc) as a person writes it by hand: one state
   variable per side, a switch over each, the transitions in the chart's order, then the
   actions. The benchmarks compare gfec's engines with this. */
#include <stdbool.h>

bool Left_IR_Black(void);
bool Left_IR_White(void);
bool Right_IR_Black(void);
bool Right_IR_White(void);
void Left_FW(void);
void Left_Stop(void);
void Right_FW(void);
void Right_Stop(void);

enum Side { FW, STOP };
typedef struct LineFollower {
  enum Side left, right;
} LineFollower;

void LineFollower_init(LineFollower *m) {
  m->left = FW;
  m->right = FW;
}

void LineFollower_run(LineFollower *m) {
  switch (m->left) {
  case FW:
    if (Left_IR_Black()) m->left = STOP;
    break;
  case STOP:
    if (Left_IR_White()) m->left = FW;
    break;
  }
  switch (m->right) {
  case FW:
    if (Right_IR_Black()) m->right = STOP;
    break;
  case STOP:
    if (Right_IR_White()) m->right = FW;
    break;
  }
  if (m->left == FW) Left_FW();
  else Left_Stop();
  if (m->right == FW) Right_FW();
  else Right_Stop();
}
