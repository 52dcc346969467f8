// The abort button of ParaView 5.11's progress bar cannot stop a filter: during a run ParaView
// takes no clicks (its progress manager blocks mouse events on the main window, the button's
// included), and the abort() signal it would emit has no receiver that stops filters. This GUI
// component makes the button work for the CVT filters: while one reports progress it lets
// events through, takes a press on the button as abort, and sets AbortExecute on the CVT
// filters of the builtin session; they check it every iteration and end with the sites so far.
#ifndef pqCVTAbortBehavior_h
#define pqCVTAbortBehavior_h

#include <QObject>
#include <QString>

class pqCVTAbortBehavior : public QObject
{
  Q_OBJECT

public:
  explicit pqCVTAbortBehavior(QObject* parent = nullptr);
  ~pqCVTAbortBehavior() override = default;

  /** Called by the plugin's auto-start interface when the GUI loads the plugin. */
  void startup();
  void shutdown();

protected:
  /** During a CVT run, a mouse press on an abort button aborts (nothing else is let through). */
  bool eventFilter(QObject* object, QEvent* event) override;

private Q_SLOTS:
  /** While a CVT filter reports progress (its progress text starts with "CVT"), allow abort. */
  void onProgress(const QString& text, int progress);
  void onProgressEnd();
  /** Asks every CVT filter of the builtin session to stop after its current iteration. */
  void abortCVTFilters();

private:
  bool CVTRunning = false;
};

#endif
