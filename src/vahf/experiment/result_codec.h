// A cycle's or a stability trial's result as bytes and back, exactly: what a
// run's journal keeps of each finished index (journal.h) so that a resumed
// run ends with the same bits as one never stopped (docs/reproducibility.md,
// "Resume"). CBOR (RFC 8949, nlohmann::json's writer) with every double
// stored as its IEEE-754 bit pattern, so that NaN's sign and payload and
// -0.0 survive: a value formatted after decoding prints as it did before.
// Measured fields (wall and CPU seconds, phase times) travel too; they are
// in no digest.
#pragma once

#include <string>

#include "vahf/experiment/design.h"
#include "vahf/experiment/stability_design.h"

namespace vahf::experiment {

std::string EncodeCycleRecord(const CycleRecord& record);
// Decodes what EncodeCycleRecord wrote; bytes that are not such an encoding
// are a ComputationError (kRefused): a journal's entries are checked by their
// digest first, so this means a bug or another program's journal.
CycleRecord DecodeCycleRecord(const std::string& bytes);
inline constexpr ResultCodec<CycleRecord> kCycleRecordCodec{EncodeCycleRecord,
                                                            DecodeCycleRecord};

std::string EncodeStabilityTrial(const StabilityTrial& trial);
StabilityTrial DecodeStabilityTrial(const std::string& bytes);
inline constexpr ResultCodec<StabilityTrial> kStabilityTrialCodec{EncodeStabilityTrial,
                                                                  DecodeStabilityTrial};

}  // namespace vahf::experiment
