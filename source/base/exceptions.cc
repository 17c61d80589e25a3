#include <deal.II/base/utilities.h>

#include <deal.II/lac/solver_control.h>

#include <fgimpact/base/exceptions.h>

#include <new>
#include <sstream>

namespace fgimpact
{


  namespace
  {
    /// A word (no spaces) of a message longer than this is shortened: a
    /// user's 5 MB value must not become a 5 MB error line.
    constexpr std::size_t max_word_length = 200;

    /// Position near `at` that does not split a UTF-8 character.
    std::size_t
    character_boundary(const std::string &text, std::size_t at)
    {
      while (at > 0 && at < text.size() &&
             (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80)
        --at;
      return at;
    }

    /// The word as printed: its head and tail around the count of the
    /// characters left out.
    std::string
    shortened(const std::string &word)
    {
      if (word.size() <= max_word_length)
        return word;
      const std::size_t head = character_boundary(word, 120);
      const std::size_t tail = character_boundary(word, word.size() - 40);
      return word.substr(0, head) + "[... " + std::to_string(tail - head) +
             " characters left out ...]" + word.substr(tail);
    }
  } // namespace



  std::string
  one_line(const std::string &text)
  {
    std::string out, word;
    const auto  end_word = [&]() {
      if (!word.empty() && !out.empty())
        out += ' ';
      out += shortened(word);
      word.clear();
    };
    for (const char ch : text)
      {
        const auto byte = static_cast<unsigned char>(ch);
        if (ch == '\n' || ch == '\r' || ch == '\t' || ch == ' ')
          end_word();
        else if (byte < 0x20 || byte == 0x7f)
          {
            // A control character (a NUL byte of a file) as \xNN.
            char escaped[8];
            std::snprintf(escaped, sizeof(escaped), "\\x%02X", byte);
            word += escaped;
          }
        else
          word += ch;
      }
    end_word();
    return out;
  }



  std::string
  message_of(const ExceptionBase &e)
  {
    std::ostringstream s;
    e.print_info(s);
    return one_line(s.str());
  }



  namespace
  {
    /// A failure's one line and exit code (`default_code` where its type
    /// does not decide); whether it is a signal's interruption (its message
    /// is printed without the caller's context).
    struct FailureText
    {
      std::string text;
      int         code;
      bool        interrupted = false;
    };

    FailureText
    failure_text(const std::exception_ptr &failure, const int default_code)
    {
      try
        {
          std::rethrow_exception(failure);
        }
      catch (const RunInterrupted &e)
        {
          return {e.message, 128 + e.signal, true};
        }
      catch (const SolverControl::NoConvergence &e)
        {
          // deal.II's text is several sentences; the caller did not say
          // where, so name the parameters.
          return {message_of(linear_solver_failure("", e.last_step)), 2};
        }
      catch (const ExcNumericalFailure &e)
        {
          return {message_of(e), 2};
        }
      catch (const ExcOutputFailure &e)
        {
          return {message_of(e), 2};
        }
      catch (const ExcResumeRefused &e)
        {
          return {message_of(e), 1};
        }
      catch (const ExceptionBase &e)
        {
          return {message_of(e), default_code};
        }
      catch (const std::bad_alloc &)
        {
          return {"out of memory (std::bad_alloc); use coarser Geometry/"
                  "Subdivisions or more MPI ranks.",
                  2};
        }
      catch (const std::exception &e)
        {
          return {one_line(e.what()), default_code};
        }
      catch (...)
        {
          return {"unknown exception.", default_code};
        }
    }
  } // namespace



  std::string
  failure_message(const std::exception_ptr &failure)
  {
    return failure_text(failure, 0).text;
  }



  int
  report_failure(const std::exception_ptr &failure,
                 const bool                root,
                 const int                 default_code,
                 const std::string        &context)
  {
    const FailureText f = failure_text(failure, default_code);
    if (root)
      std::cerr << "fgimpact: " << (f.interrupted ? "" : context + ": ")
                << f.text << std::endl;
    return f.code;
  }



  ExcNumericalFailure
  linear_solver_failure(const std::string &where, const unsigned int iterations)
  {
    return ExcNumericalFailure(
      "the linear solver did not converge" +
      (where.empty() ? std::string() : " " + where) + " after " +
      std::to_string(iterations) +
      " iterations; raise Linear solver/Max iterations or use a direct "
      "solver (Linear solver/Type = auto or cholmod).");
  }



  bool
  is_numerical_failure(const std::exception_ptr &failure)
  {
    try
      {
        std::rethrow_exception(failure);
      }
    catch (const ExcNumericalFailure &)
      {
        return true;
      }
    catch (...)
      {
        return false;
      }
  }



  bool
  is_run_failure(const std::exception_ptr &failure)
  {
    try
      {
        std::rethrow_exception(failure);
      }
    catch (const SolverControl::NoConvergence &)
      {
        return true;
      }
    catch (const ExcNumericalFailure &)
      {
        return true;
      }
    catch (const ExcOutputFailure &)
      {
        return true;
      }
    catch (const std::bad_alloc &)
      {
        return true;
      }
    catch (...)
      {
        return false;
      }
  }



  void
  run_on_root(const MPI_Comm comm, const std::function<void()> &f)
  {
    // The outcome as a string: its first character is the kind.
    std::string failure = "0";
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          f();
        }
      catch (const ExcOutputFailure &e)
        {
          failure = "2" + message_of(e);
        }
      catch (const ExceptionBase &e)
        {
          failure = "1" + message_of(e);
        }
      catch (const std::exception &e)
        {
          failure = "1" + one_line(e.what());
        }
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      failure = Utilities::MPI::broadcast(comm, failure, 0);
    AssertThrow(failure[0] != '2', ExcOutputFailure(failure.substr(1)));
    AssertThrow(failure[0] != '1', ExcMessage(failure.substr(1)));
  }
} // namespace fgimpact
