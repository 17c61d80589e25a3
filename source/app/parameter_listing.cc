#include <fgimpact/app/command_line.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fgimpact
{
  namespace CommandLine
  {
    namespace
    {
      /// ParameterHandler's tree keys spell every character other than a
      /// letter or digit as _xx (hex).
      std::string
      demangle(const std::string &key)
      {
        std::string name;
        for (std::size_t i = 0; i < key.size(); ++i)
          if (key[i] == '_' && i + 2 < key.size() &&
              std::isxdigit(static_cast<unsigned char>(key[i + 1])) &&
              std::isxdigit(static_cast<unsigned char>(key[i + 2])))
            {
              name +=
                static_cast<char>(std::stoi(key.substr(i + 1, 2), nullptr, 16));
              i += 2;
            }
          else
            name += key[i];
        return name;
      }

      /// "Section/Entry" -> the entry's pattern description.
      void
      collect_patterns(const boost::property_tree::ptree  &tree,
                       const std::string                  &path,
                       std::map<std::string, std::string> &patterns)
      {
        for (const auto &[key, node] : tree)
          {
            const std::string name = path + demangle(key);
            if (const auto description =
                  node.get_optional<std::string>("pattern_description"))
              patterns[name] = *description;
            else
              collect_patterns(node, name + "/", patterns);
          }
      }

      std::string
      trim(const std::string &s)
      {
        const auto begin = s.find_first_not_of(" \t");
        const auto end   = s.find_last_not_of(" \t");
        return begin == std::string::npos ? "" :
                                            s.substr(begin, end - begin + 1);
      }
    } // namespace



    void
    print_parameters(const dealii::ParameterHandler &prm, std::ostream &out)
    {
      std::stringstream json;
      prm.print_parameters(json, dealii::ParameterHandler::JSON);
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      std::map<std::string, std::string> patterns;
      collect_patterns(tree, "", patterns);

      // The PRM listing, with "# Allowed: ..." before every `set` line
      // (indented like it), found by the subsection path.
      std::stringstream listing;
      prm.print_parameters(listing, dealii::ParameterHandler::PRM);
      std::vector<std::string> sections;
      std::string              line;
      while (std::getline(listing, line))
        {
          const std::string text = trim(line);
          const std::string indent =
            line.substr(0, line.find_first_not_of(' '));
          if (text.rfind("subsection ", 0) == 0)
            sections.push_back(trim(text.substr(11)));
          else if (text == "end" && !sections.empty())
            sections.pop_back();
          else if (text.rfind("set ", 0) == 0)
            {
              std::string path;
              for (const auto &section : sections)
                path += section + "/";
              const std::string name = trim(text.substr(4, text.find('=') - 4));
              const auto        pattern = patterns.find(path + name);
              if (pattern != patterns.end())
                out << indent << "# Allowed: " << pattern->second << '\n';
            }
          out << line << '\n';
        }
    }
  } // namespace CommandLine
} // namespace fgimpact
