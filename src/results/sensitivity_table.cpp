#include "twb/results/sensitivity_table.h"

namespace twb {

ResultTable sensitivity_table(const std::vector<SensitivityRow>& rows) {
  ResultTable t;
  const auto quantity = t.text("quantity"), value = t.number("value"), parameter = t.text("parameter"),
             parameter_value = t.number("parameter_value"), unit = t.text("parameter_unit"),
             derivative = t.number("derivative"), elasticity = t.number("elasticity"), step = t.number("step");
  for (const SensitivityRow& r : rows) {
    t.put_text(quantity, r.quantity);
    t.put_number(value, r.value);
    t.put_text(parameter, r.parameter);
    t.put_number(parameter_value, r.parameter_value);
    t.put_text(unit, r.parameter_unit);
    t.put_number(derivative, r.derivative);
    t.put_number(elasticity, r.elasticity);
    t.put_number(step, r.step);
  }
  return t;
}

}  // namespace twb
