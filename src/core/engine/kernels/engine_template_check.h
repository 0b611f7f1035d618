/* engine_template_check.h: included after a block of template instances (engine_spatial.h,
 * engine_spatial_inertia.h, engine_invsym.h, engine_trig.h, engine_quat.h, engine_kin.h,
 * engine_aba.h): fails the build if any template parameter is still defined, so that every
 * instance undefines what it defined and the next one starts clean (src/README, "Templates").
 * No include guard: included once per block. */
#if defined(urT) || defined(urM) || defined(urU) || defined(urK) || defined(urFN) ||               \
    defined(urD) || defined(urBC) || defined(urSEL) || defined(urANY) || defined(urALL) ||         \
    defined(urNEL) || defined(urEL) || defined(urASI) || defined(urAST) || defined(urSQRT) ||      \
    defined(urSTORAGE) || defined(urSETENERGY) || defined(urINVSYM) || defined(urAXISROT) ||       \
    defined(urABA_ATTR) || defined(urKIN_ATTR) || defined(urKIN_PRE) || defined(urCROSSK) ||       \
    defined(urSTEPH) || defined(urINVUNROLL)
#error "a template parameter is still defined after its instances (src/README, Templates)"
#endif
