// Collects the first error message a VTK reader raises instead of letting VTK print it:
//   VtkErrors errors;
//   reader->AddObserver(vtkCommand::ErrorEvent, errors.callback);
#pragma once

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkSmartPointer.h>

#include <string>

namespace sph {

struct VtkErrors {
    std::string text;
    vtkSmartPointer<vtkCallbackCommand> callback = vtkSmartPointer<vtkCallbackCommand>::New();
    VtkErrors() {
        callback->SetClientData(this);
        callback->SetCallback([](vtkObject*, unsigned long, void* self, void* message) {
            auto* errors = static_cast<VtkErrors*>(self);
            if (errors->text.empty() && message) errors->text = static_cast<const char*>(message);
        });
    }
    std::string firstLine() const { return text.substr(0, text.find('\n')); }
};

}  // namespace sph
