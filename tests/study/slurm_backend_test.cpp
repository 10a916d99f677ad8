// The job-array script: one task per case to run, sbatch's own flags from the study's options,
// each task the same `fabform run` the local pool starts, its words quoted for sh.
#include "fabform/study/slurm_backend.hpp"

#include <gtest/gtest.h>

namespace fabform::slurm_backend_test {
namespace {

TEST(SlurmBackend, ScriptMapsOptionsToSbatchFlagsAndRunsEachCase) {
  StudySpec spec;
  spec.name = "s";
  spec.scene = "/scenes/a b.toml";
  spec.varied = {"body.0.friction"};
  for (const char* mu : {"0.1", "0.2", "0.3"}) spec.cases.push_back({{{"body.0.friction", mu, mu, {}}}});
  const std::string script = slurm_script(spec, "/studies/x", {0, 2}, {"short", 30, 2048, 2, 1}, "/bin/fabform");
  for (const char* line : {"#SBATCH --array=0,2%1\n", "#SBATCH --cpus-per-task=2\n", "#SBATCH --partition='short'\n",
                           "#SBATCH --time=30\n", "#SBATCH --mem=2048\n", "#SBATCH --output='/studies/x/slurm/case-%a.log'\n",
                           "  2) exec '/bin/fabform' 'run' '/scenes/a b.toml' '--set' 'body.0.friction=0.3' '--out' "
                           "'/studies/x/cases/0002' '--quiet' '--threads' '2' ;;\n"})
    EXPECT_NE(script.find(line), std::string::npos) << line << "\nnot in\n" << script;
  EXPECT_EQ(script.find("  1)"), std::string::npos);
  const std::string plain = slurm_script(spec, "/studies/x", {1}, {}, "/bin/fabform");
  EXPECT_EQ(plain.find("--partition"), std::string::npos);
  EXPECT_EQ(plain.find("--time"), std::string::npos);
  EXPECT_EQ(plain.find("--mem"), std::string::npos);
}

}  // namespace
}  // namespace fabform::slurm_backend_test
