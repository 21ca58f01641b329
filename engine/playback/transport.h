// The player's clock and transport: play, pause, step, a loop range, ping-pong and speed. Frames
// are 0 .. frameCount - 1 at 1/fps seconds apart; the range [in, out] is inclusive. The position
// is kept to a fraction of a frame so that playing at speed s for t seconds of wall time moves
// s t fps frames whatever the call rate. No clock of its own: the caller passes elapsed time.
#pragma once

namespace ib::play {

class Transport {
 public:
  // Paused at frame 0, loop on, ping-pong off, range = all, speed 1. frameCount >= 1, fps > 0
  // (std::invalid_argument otherwise: a timeline always has both).
  Transport(int frameCount, double fps);

  // play() from the out point when neither looping nor ping-ponging starts again from the in point.
  void play();
  void pause();
  void toggle();
  bool playing() const;

  // Pauses; moves `frames` (negative: back) within the range, wrapping when looping, else clamping.
  void step(int frames);
  // Clamped to the timeline (not the range); keeps the playing state. Playing from outside the
  // range goes to the in point first.
  void goTo(int frame);
  void toStart();  // the range's in point, playing forward; keeps the playing state
  void toEnd();    // the range's out point; keeps the playing state

  void setLoop(bool on);
  bool loop() const;
  // At the ends: reverse instead of wrapping. At the in point, coming back: reverses again when
  // looping, else stops there.
  void setPingPong(bool on);
  bool pingPong() const;
  // Clamped to the timeline; swapped when in > out. Keeps the frame.
  void setRange(int in, int out);
  int in() const;
  int out() const;
  void setSpeed(double speed);  // clamped to [0.1, 4]; non-finite leaves it
  double speed() const;

  // Advances the clock by `seconds` of wall time while playing (speed applied); at the out point:
  // wraps to the in point (loop), reverses (ping-pong) or stops (neither). Returns frame().
  int advance(double seconds);
  int frame() const;
  double time() const;  // seconds on the timeline of frame(), from its start: frame() / fps
  int frameCount() const;
  double fps() const;
  bool forward() const;  // the direction of play (false on ping-pong's way back)

 private:
  void enterRange();  // a frame outside [in, out] jumps to the in point; ping-pong keeps within [in, out]

  int frameCount_;
  double fps_;
  double position_ = 0;  // frames; frame() is its floor going forward and its ceiling going back
  bool forward_ = true;
  bool playing_ = false;
  bool loop_ = true;
  bool pingPong_ = false;
  int in_ = 0, out_ = 0;
  double speed_ = 1;
};

}  // namespace ib::play
