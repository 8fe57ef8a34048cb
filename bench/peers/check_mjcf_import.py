"""What MuJoCo itself compiles from tests/fixtures/import/muscles.xml, the MJCF file that
tests/io/muscle_import_test.cc imports: each actuator's gain, bias and dynamics parameters
and its length range, to set beside what `musclesim import` reads (the test's expected
values were taken from this output).

    "$(bash bench/peers/setup.sh)" bench/peers/check_mjcf_import.py
"""
import os

import mujoco

HERE = os.path.dirname(os.path.abspath(__file__))
path = os.path.join(HERE, "..", "..", "tests", "fixtures", "import", "muscles.xml")
model = mujoco.MjModel.from_xml_path(path)
for i in range(model.nu):
    def numbers(values):
        return [float(v) for v in values]

    print(mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, i),
          "gainprm", numbers(model.actuator_gainprm[i, :9]),
          "biasprm", numbers(model.actuator_biasprm[i, :9]),
          "dyntype", int(model.actuator_dyntype[i]), "dynprm", numbers(model.actuator_dynprm[i, :3]),
          "lengthrange", numbers(model.actuator_lengthrange[i]),
          "acc0", float(model.actuator_acc0[i]))
