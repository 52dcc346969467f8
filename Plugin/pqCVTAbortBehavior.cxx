#include "pqCVTAbortBehavior.h"

#include "pqApplicationCore.h"
#include "pqCoreUtilities.h"
#include "pqPipelineSource.h"
#include "pqProgressManager.h"
#include "pqServerManagerModel.h"
#include "vtkAlgorithm.h"
#include "vtkSMProxy.h"

#include <QApplication>
#include <QMouseEvent>
#include <QWidget>

#include <cstring>

//-----------------------------------------------------------------------------
pqCVTAbortBehavior::pqCVTAbortBehavior(QObject* parent)
  : QObject(parent)
{
}

//-----------------------------------------------------------------------------
void pqCVTAbortBehavior::startup()
{
  pqProgressManager* progress = pqApplicationCore::instance()->getProgressManager();
  QObject::connect(progress, &pqProgressManager::abort, this, &pqCVTAbortBehavior::abortCVTFilters);
  QObject::connect(progress, &pqProgressManager::progress, this, &pqCVTAbortBehavior::onProgress);
  QObject::connect(
    progress, &pqProgressManager::progressEndEvent, this, &pqCVTAbortBehavior::onProgressEnd);
  // Installed after the progress manager's filter, so it sees events first.
  QApplication::instance()->installEventFilter(this);
}

//-----------------------------------------------------------------------------
void pqCVTAbortBehavior::shutdown()
{
  QApplication::instance()->removeEventFilter(this);
}

//-----------------------------------------------------------------------------
void pqCVTAbortBehavior::onProgress(const QString& text, int)
{
  if (!text.startsWith("CVT"))
  {
    return;
  }
  if (!this->CVTRunning)
  {
    this->CVTRunning = true;
    pqApplicationCore::instance()->getProgressManager()->setEnableAbort(true);
  }
  // ParaView repaints the progress bar during a run but takes no user input; process it here.
  // The progress manager still drops key and mouse presses, and this filter takes the ones on
  // the abort button.
  QApplication::processEvents();
}

//-----------------------------------------------------------------------------
void pqCVTAbortBehavior::onProgressEnd()
{
  if (this->CVTRunning)
  {
    this->CVTRunning = false;
    pqApplicationCore::instance()->getProgressManager()->setEnableAbort(false);
  }
}

//-----------------------------------------------------------------------------
bool pqCVTAbortBehavior::eventFilter(QObject* object, QEvent* event)
{
  if (this->CVTRunning && event->type() == QEvent::MouseButtonPress)
  {
    // Qt's own hit test: the press arrives at the main window, not at the button.
    QWidget* target = QApplication::widgetAt(static_cast<QMouseEvent*>(event)->globalPos());
    for (; target; target = target->parentWidget())
    {
      if (target->objectName() == "AbortButton")
      {
        this->abortCVTFilters();
        return true;
      }
    }
  }
  return this->QObject::eventFilter(object, event);
}

//-----------------------------------------------------------------------------
void pqCVTAbortBehavior::abortCVTFilters()
{
  // Only the filters run in this process (the builtin session) can be reached: on a remote
  // server the client-side object is a stub and the run goes on.
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  for (pqPipelineSource* source : model->findItems<pqPipelineSource*>())
  {
    vtkSMProxy* proxy = source->getProxy();
    const char* name = proxy ? proxy->GetXMLName() : nullptr;
    if (!name || std::strncmp(name, "CVT", 3) != 0)
    {
      continue;
    }
    if (auto* algorithm = vtkAlgorithm::SafeDownCast(proxy->GetClientSideObject()))
    {
      algorithm->SetAbortExecute(1);
    }
  }
}
