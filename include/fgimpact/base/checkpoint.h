#ifndef fgimpact_checkpoint_h
#define fgimpact_checkpoint_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_vector.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * @name Checkpoint and resume
   *
   * A checkpoint is the complete state of an impact run after a time step:
   * each MPI rank writes one binary file, OUTPUT/checkpoint/rank_NNNN.bin,
   * with a header (magic, format version, rank count, step, a hash and the
   * text of the expanded parameters) and a payload the driver fills
   * (CheckpointWriter: one named, versioned section per component, each
   * with its scalar state, identical on every rank, and this rank's part
   * of its distributed vectors; the partition is the same for the same
   * mesh and rank count).  Values are stored as their bytes, so a
   * resumed run continues bit for bit.  The files go to checkpoint.new/;
   * only once every rank has written its file does rank 0 put that
   * directory in the place of the last good one (checkpoint.old/ in
   * between, which resume also accepts), so a run killed at any moment
   * leaves a complete checkpoint.
   */
  /** @{ */

  /// The payload of a checkpoint, appended value by value.
  class CheckpointWriter
  {
  public:
    template <typename T>
    void
    put(const T &value)
    {
      static_assert(std::is_trivially_copyable<T>::value, "plain values");
      buffer.append(reinterpret_cast<const char *>(&value), sizeof(T));
    }
    void
    put(const std::string &text);
    void
    put(const std::vector<double> &values);
    void
    put(const std::vector<bool> &values);
    /// This rank's locally owned entries of a distributed vector.
    void
    put(const TrilinosWrappers::MPI::Vector &vector);

    /**
     * A named, versioned section: what save(CheckpointWriter &) puts into
     * a writer of its own, stored with its name, version and length.
     * CheckpointReader::section() finds it by name, so each component
     * saves and loads its own section and the order of the calls does not
     * matter; a component that changes its layout raises its version.
     */
    template <typename Save>
    void
    section(const std::string  &name,
            const std::uint32_t version,
            const Save         &save)
    {
      CheckpointWriter part;
      save(part);
      put(name);
      put(version);
      put(part.buffer);
    }

    const std::string &
    data() const
    {
      return buffer;
    }

  private:
    std::string buffer;
  };



  /// Reads a payload in the order it was written; throws ExcMessage if the
  /// data run out or a vector does not match this rank's partition.
  class CheckpointReader
  {
  public:
    explicit CheckpointReader(std::string data);

    template <typename T>
    void
    get(T &value)
    {
      static_assert(std::is_trivially_copyable<T>::value, "plain values");
      std::memcpy(&value, take(sizeof(T)), sizeof(T));
    }
    void
    get(std::string &text);
    void
    get(std::vector<double> &values);
    void
    get(std::vector<bool> &values);
    void
    get(TrilinosWrappers::MPI::Vector &vector);

    /**
     * The section `name` written by CheckpointWriter::section(), wherever
     * it lies in the payload (the reader's position does not move).
     * Throws ExcMessage if it is missing or has another version.
     */
    CheckpointReader
    section(const std::string &name, const std::uint32_t version) const;

    /// The step the checkpoint was written after.
    unsigned int step = 0;

  private:
    const char *
    take(const std::size_t n);

    std::string buffer;
    std::size_t position = 0;
  };



  /// What the executable tells an impact run about checkpoints.
  struct CheckpointSettings
  {
    /// The expanded parameters (ParameterHandler, PRM | Short), stored in
    /// every checkpoint and compared on resume.
    std::string parameters_text;
    /// Resume from the checkpoint in this output directory ("" = a new
    /// run).
    std::string resume_directory;
    /// The time step of that checkpoint (check_resume(), known before the
    /// set-up, so that a resume past End time is refused before any file
    /// is written).
    unsigned int resume_step = 0;
    /// Called on every rank once a resume is accepted (the checkpoint read,
    /// every output file found continuable), before anything is written:
    /// the application writes parameters.prm then, so that a refused resume
    /// leaves it as it was.
    std::function<void()> on_resume_accepted;
  };

  /**
   * Write this rank's payload as checkpoint step `step` in directory
   * (collective): every rank writes checkpoint.new/rank_NNNN.bin, all agree
   * that all succeeded, then rank 0 renames checkpoint.new to checkpoint.
   * Throws ExcOutputFailure (naming the file) on every rank if any rank
   * failed; the last good checkpoint stays.
   */
  void
  write_checkpoint(const std::string &directory,
                   const MPI_Comm     comm,
                   const unsigned int step,
                   const std::string &parameters_text,
                   const std::string &payload);

  /**
   * This rank's payload of the checkpoint in directory (collective),
   * checked: the format, the rank count, the payload's hash, the same step
   * on every rank.  Throws ExcMessage naming the problem.
   */
  CheckpointReader
  read_checkpoint(const std::string &directory, const MPI_Comm comm);

  /**
   * Before resuming (rank 0): throws ExcMessage with one line if the
   * checkpoint in directory is missing, was written by a different number
   * of ranks, or its parameters differ from parameters_text in an entry
   * that changes the answer (every entry but Output/Directory, Log
   * interval, Print timing, Overwrite, Checkpoint interval and Time
   * integration/End time), naming the entries.  Returns the checkpoint's
   * time step.
   */
  unsigned int
  check_resume(const std::string &directory,
               const std::string &parameters_text,
               const unsigned int n_ranks);

  /// The subdirectories a run's checkpoints use (for Output/Overwrite).
  bool
  is_checkpoint_directory(const std::string &name);
  /** @} */
} // namespace fgimpact

#endif
